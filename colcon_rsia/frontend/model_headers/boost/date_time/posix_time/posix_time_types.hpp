// colcon-rsia model of <boost/date_time/posix_time/posix_time_types.hpp>.
#include <rsia_model/boost_asio.h>
