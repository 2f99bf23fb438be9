// colcon-rsia model of <tf2/LinearMath/Scalar.hpp> (ROS 2 Jazzy and newer)
#include <tf2/LinearMath/Scalar.h>
