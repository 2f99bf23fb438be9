// colcon-rsia model of <class_loader/class_loader.hpp>.
#include <class_loader/class_loader_core.hpp>
#include <class_loader/register_macro.hpp>
