// colcon-rsia model of <boost/thread/thread.hpp>.
#include <rsia_model/boost_thread.h>
