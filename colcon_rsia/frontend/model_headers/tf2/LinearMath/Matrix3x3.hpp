// colcon-rsia model of <tf2/LinearMath/Matrix3x3.hpp> (ROS 2 Jazzy and newer)
#include <tf2/LinearMath/Matrix3x3.h>
