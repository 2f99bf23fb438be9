// colcon-rsia model of <boost/smart_ptr.hpp>.
#include <boost/make_shared.hpp>
#include <boost/scoped_ptr.hpp>
#include <boost/shared_ptr.hpp>
