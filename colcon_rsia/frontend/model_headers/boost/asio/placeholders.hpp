// colcon-rsia model of <boost/asio/placeholders.hpp>.
#include <rsia_model/boost_asio.h>
