// colcon-rsia model of <tf2_geometry_msgs/tf2_geometry_msgs.hpp> (ROS 2):
// the same declarations as the ROS 1 header.
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>
