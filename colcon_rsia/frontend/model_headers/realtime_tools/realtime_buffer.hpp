// colcon-rsia model of <realtime_tools/realtime_buffer.hpp> (ROS 2): the
// same class as the ROS 1 header, see <realtime_tools/realtime_buffer.h>.
#include <realtime_tools/realtime_buffer.h>
