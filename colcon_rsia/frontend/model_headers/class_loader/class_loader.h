// colcon-rsia model of <class_loader/class_loader.h> (ROS 1 spelling).
#include <class_loader/class_loader.hpp>
