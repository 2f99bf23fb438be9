// colcon-rsia model of <boost/core/ref.hpp>.
#include <boost/ref.hpp>
