// colcon-rsia model of <boost/thread/mutex.hpp>.
#include <rsia_model/boost_thread.h>
