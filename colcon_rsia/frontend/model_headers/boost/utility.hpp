// colcon-rsia model of <boost/utility.hpp>.
#include <boost/noncopyable.hpp>
