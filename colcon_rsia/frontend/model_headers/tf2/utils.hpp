// colcon-rsia model of <tf2/utils.hpp> (ROS 2, newer name of <tf2/utils.h>)
#include <tf2/utils.h>
