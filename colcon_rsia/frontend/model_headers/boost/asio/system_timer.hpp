// colcon-rsia model of <boost/asio/system_timer.hpp>.
#include <rsia_model/boost_asio.h>
