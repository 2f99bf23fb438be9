// colcon-rsia model of <tf2/LinearMath/Quaternion.hpp> (ROS 2 Jazzy and newer)
#include <tf2/LinearMath/Quaternion.h>
