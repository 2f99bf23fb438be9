// colcon-rsia model of <behaviortree_cpp_v3/control_node.h> (BehaviorTree.CPP 3):
// the same declarations as behaviortree_cpp/tree_node.h.
#ifndef RSIA_MODEL_BEHAVIORTREE_CPP_V3_CONTROL_NODE_H
#define RSIA_MODEL_BEHAVIORTREE_CPP_V3_CONTROL_NODE_H
#include <behaviortree_cpp/tree_node.h>
#endif  // RSIA_MODEL_BEHAVIORTREE_CPP_V3_CONTROL_NODE_H
