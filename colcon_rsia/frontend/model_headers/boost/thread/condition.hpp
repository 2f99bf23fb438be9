// colcon-rsia model of <boost/thread/condition.hpp>.
#include <rsia_model/boost_thread.h>
