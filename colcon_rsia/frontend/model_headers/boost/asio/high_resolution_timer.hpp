// colcon-rsia model of <boost/asio/high_resolution_timer.hpp>.
#include <rsia_model/boost_asio.h>
