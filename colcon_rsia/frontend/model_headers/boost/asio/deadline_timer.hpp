// colcon-rsia model of <boost/asio/deadline_timer.hpp>.
#include <rsia_model/boost_asio.h>
