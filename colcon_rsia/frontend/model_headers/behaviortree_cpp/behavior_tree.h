// colcon-rsia model of <behaviortree_cpp/behavior_tree.h>: see tree_node.h.
#ifndef RSIA_MODEL_BEHAVIORTREE_CPP_BEHAVIOR_TREE_H
#define RSIA_MODEL_BEHAVIORTREE_CPP_BEHAVIOR_TREE_H
#include <behaviortree_cpp/tree_node.h>
#endif  // RSIA_MODEL_BEHAVIORTREE_CPP_BEHAVIOR_TREE_H
