// colcon-rsia model of <boost/thread/once.hpp>.
#include <rsia_model/boost_thread.h>
