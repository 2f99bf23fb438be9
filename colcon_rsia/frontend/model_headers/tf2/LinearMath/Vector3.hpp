// colcon-rsia model of <tf2/LinearMath/Vector3.hpp> (ROS 2 Jazzy and newer)
#include <tf2/LinearMath/Vector3.h>
