// colcon-rsia model of <boost/thread/thread_only.hpp>.
#include <rsia_model/boost_thread.h>
