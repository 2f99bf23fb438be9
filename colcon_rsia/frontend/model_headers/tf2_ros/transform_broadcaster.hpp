// colcon-rsia model of <tf2_ros/transform_broadcaster.hpp> (ROS 2 Jazzy+ name)
#include <tf2_ros/transform_broadcaster.h>
