// colcon-rsia model of <tf2_ros/transform_listener.hpp> (ROS 2 Jazzy+ name)
#include <tf2_ros/transform_listener.h>
