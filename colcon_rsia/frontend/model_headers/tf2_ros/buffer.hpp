// colcon-rsia model of <tf2_ros/buffer.hpp> (ROS 2 Jazzy+ name)
#include <tf2_ros/buffer.h>
