// colcon-rsia model of <behaviortree_cpp/bt_factory.h>: see tree_node.h.
#ifndef RSIA_MODEL_BEHAVIORTREE_CPP_BT_FACTORY_H
#define RSIA_MODEL_BEHAVIORTREE_CPP_BT_FACTORY_H
#include <behaviortree_cpp/tree_node.h>
#endif  // RSIA_MODEL_BEHAVIORTREE_CPP_BT_FACTORY_H
