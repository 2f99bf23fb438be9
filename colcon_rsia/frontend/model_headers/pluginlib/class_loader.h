// colcon-rsia model of <pluginlib/class_loader.h> (ROS 1 name)
#include <pluginlib/class_loader.hpp>
