// colcon-rsia model of <boost/thread/lock_guard.hpp>.
#include <rsia_model/boost_thread.h>
