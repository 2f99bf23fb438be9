// colcon-rsia model of <behaviortree_cpp_v3/behavior_tree.h> (BehaviorTree.CPP 3):
// the same declarations as behaviortree_cpp/tree_node.h.
#ifndef RSIA_MODEL_BEHAVIORTREE_CPP_V3_BEHAVIOR_TREE_H
#define RSIA_MODEL_BEHAVIORTREE_CPP_V3_BEHAVIOR_TREE_H
#include <behaviortree_cpp/tree_node.h>
#endif  // RSIA_MODEL_BEHAVIORTREE_CPP_V3_BEHAVIOR_TREE_H
