// colcon-rsia model of <boost/thread.hpp>.
#include <rsia_model/boost_thread.h>
