// colcon-rsia model of <boost/asio.hpp>.
#include <rsia_model/boost_asio.h>
