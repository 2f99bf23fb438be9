// colcon-rsia model of <boost/date_time/posix_time/posix_time.hpp>.
#include <rsia_model/boost_asio.h>
