// colcon-rsia model of <boost/asio/io_context.hpp>.
#include <rsia_model/boost_asio.h>
