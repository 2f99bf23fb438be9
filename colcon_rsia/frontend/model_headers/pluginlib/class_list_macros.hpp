// colcon-rsia model of <pluginlib/class_list_macros.hpp>: PLUGINLIB_EXPORT_CLASS
// (a macro instantiation the analysis reads for nodelet exports).
#ifndef RSIA_MODEL_PLUGINLIB_CLASS_LIST_MACROS_HPP
#define RSIA_MODEL_PLUGINLIB_CLASS_LIST_MACROS_HPP

#include <class_loader/class_loader.hpp>

#define PLUGINLIB_EXPORT_CLASS(class_type, base_class_type) \
  CLASS_LOADER_REGISTER_CLASS(class_type, base_class_type)

#endif  // RSIA_MODEL_PLUGINLIB_CLASS_LIST_MACROS_HPP
