// colcon-rsia model of <behaviortree_cpp/condition_node.h>: see tree_node.h.
#ifndef RSIA_MODEL_BEHAVIORTREE_CPP_CONDITION_NODE_H
#define RSIA_MODEL_BEHAVIORTREE_CPP_CONDITION_NODE_H
#include <behaviortree_cpp/tree_node.h>
#endif  // RSIA_MODEL_BEHAVIORTREE_CPP_CONDITION_NODE_H
