// colcon-rsia model of <boost/system/error_code.hpp>.
#include <rsia_model/boost_asio.h>
