// colcon-rsia model of <boost/thread/locks.hpp>.
#include <rsia_model/boost_thread.h>
