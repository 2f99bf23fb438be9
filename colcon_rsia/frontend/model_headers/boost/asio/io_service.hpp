// colcon-rsia model of <boost/asio/io_service.hpp>.
#include <rsia_model/boost_asio.h>
