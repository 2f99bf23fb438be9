// colcon-rsia model of <boost/weak_ptr.hpp> (declared with shared_ptr).
#include <boost/shared_ptr.hpp>
