// colcon-rsia model of <boost/asio/steady_timer.hpp>.
#include <rsia_model/boost_asio.h>
