// colcon-rsia model of <boost/enable_shared_from_this.hpp> (declared with shared_ptr).
#include <boost/shared_ptr.hpp>
