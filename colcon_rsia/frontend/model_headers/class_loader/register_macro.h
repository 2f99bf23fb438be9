// colcon-rsia model of <class_loader/register_macro.h> (ROS 1 spelling).
#include <class_loader/register_macro.hpp>
