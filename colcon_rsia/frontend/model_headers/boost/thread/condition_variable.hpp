// colcon-rsia model of <boost/thread/condition_variable.hpp>.
#include <rsia_model/boost_thread.h>
