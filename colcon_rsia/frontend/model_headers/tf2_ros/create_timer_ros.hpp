// colcon-rsia model of <tf2_ros/create_timer_ros.hpp> (ROS 2 Jazzy+ name)
#include <tf2_ros/create_timer_ros.h>
