// colcon-rsia model of <boost/thread/recursive_mutex.hpp>.
#include <rsia_model/boost_thread.h>
