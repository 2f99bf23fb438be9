// colcon-rsia model of <class_loader/class_loader_register_macro.h> (ROS 1).
#include <class_loader/register_macro.hpp>
