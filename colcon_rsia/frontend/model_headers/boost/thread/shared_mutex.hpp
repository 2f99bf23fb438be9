// colcon-rsia model of <boost/thread/shared_mutex.hpp>.
#include <rsia_model/boost_thread.h>
