// colcon-rsia model of <rclcpp_components/register_node_macro.hpp> (ROS 2):
// the registration is read from the source text by the analysis; the macro
// expands to a declaration that names the class, so it must exist.
#ifndef RSIA_MODEL_RCLCPP_COMPONENTS_REGISTER_NODE_MACRO_HPP
#define RSIA_MODEL_RCLCPP_COMPONENTS_REGISTER_NODE_MACRO_HPP

#define RSIA_MODEL_CAT2(a, b) a##b
#define RSIA_MODEL_CAT(a, b) RSIA_MODEL_CAT2(a, b)
#define RCLCPP_COMPONENTS_REGISTER_NODE(NodeClass) \
  static const auto RSIA_MODEL_CAT(rsia_model_component_, __LINE__) = \
    sizeof(NodeClass);

#endif  // RSIA_MODEL_RCLCPP_COMPONENTS_REGISTER_NODE_MACRO_HPP
