// colcon-rsia model of <pluginlib/class_list_macros.h> (the ROS 1 spelling).
#include <pluginlib/class_list_macros.hpp>
