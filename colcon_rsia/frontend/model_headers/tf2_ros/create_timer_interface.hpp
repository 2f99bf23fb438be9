// colcon-rsia model of <tf2_ros/create_timer_interface.hpp> (ROS 2 Jazzy+ name)
#include <tf2_ros/create_timer_interface.h>
