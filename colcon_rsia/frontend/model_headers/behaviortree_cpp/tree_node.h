// colcon-rsia model of BehaviorTree.CPP (<behaviortree_cpp/tree_node.h> and
// the headers that include it; v3's <behaviortree_cpp_v3/...> alike):
// written from the library's documentation (behaviortree.dev). A node
// registered with BT_REGISTER_NODES is ticked by the executor that loads
// the plugin (navigation2's bt_navigator): see plugin_hosts.py.
#ifndef RSIA_MODEL_BEHAVIORTREE_CPP_TREE_NODE_H
#define RSIA_MODEL_BEHAVIORTREE_CPP_TREE_NODE_H

#include <functional>
#include <memory>
#include <string>
#include <unordered_map>

#include <rsia_model/message.h>

namespace BT
{

enum class NodeStatus { IDLE = 0, RUNNING, SUCCESS, FAILURE, SKIPPED };

class Blackboard
{
public:
  using Ptr = std::shared_ptr<Blackboard>;
  template <typename T>
  T get(const std::string& key) const;
  template <typename T>
  bool get(const std::string& key, T& value) const;
  template <typename T>
  void set(const std::string& key, const T& value);
};

struct PortInfo
{
};
using PortsList = std::unordered_map<std::string, PortInfo>;

template <typename T>
std::pair<std::string, PortInfo> InputPort(const std::string& name,
                                           const std::string& description = {});
template <typename T>
std::pair<std::string, PortInfo> OutputPort(const std::string& name,
                                            const std::string& description = {});

struct NodeConfig
{
  Blackboard::Ptr blackboard;
};
using NodeConfiguration = NodeConfig;

// what getInput returns: a value that converts to the port's type and
// tells whether it was there
template <typename T>
struct Expected
{
  explicit operator bool() const;
  const T& value() const;
  const T& operator*() const;
  const T* operator->() const;
  std::string error() const;
};

class TreeNode
{
public:
  TreeNode(std::string name, NodeConfig config);
  virtual ~TreeNode();
  virtual NodeStatus tick() = 0;
  virtual void halt();
  const std::string& name() const;
  NodeStatus status() const;
  const NodeConfig& config() const;
  NodeConfig& config();
  template <typename T>
  Expected<T> getInput(const std::string& key) const;
  template <typename T>
  Expected<T> getInput(const std::string& key, T& destination) const;
  template <typename T>
  Expected<T> setOutput(const std::string& key, const T& value);
};

class LeafNode : public TreeNode
{
public:
  using TreeNode::TreeNode;
};

class ActionNodeBase : public LeafNode
{
public:
  using LeafNode::LeafNode;
  void halt() override;
};

class SyncActionNode : public ActionNodeBase
{
public:
  SyncActionNode(const std::string& name, const NodeConfig& config);
};

class StatefulActionNode : public ActionNodeBase
{
public:
  using ActionNodeBase::ActionNodeBase;
  NodeStatus tick() override;
  void halt() override;
  virtual NodeStatus onStart() = 0;
  virtual NodeStatus onRunning() = 0;
  virtual void onHalted() = 0;
};

class ConditionNode : public LeafNode
{
public:
  ConditionNode(const std::string& name, const NodeConfig& config);
};

class DecoratorNode : public TreeNode
{
public:
  DecoratorNode(const std::string& name, const NodeConfig& config);
  void halt() override;

protected:
  TreeNode* child_node_;
};

class ControlNode : public TreeNode
{
public:
  ControlNode(const std::string& name, const NodeConfig& config);
  void halt() override;
};

class BehaviorTreeFactory
{
public:
  BehaviorTreeFactory();
  template <typename T>
  void registerNodeType(const std::string& id);
  template <typename T, typename... ExtraArgs>
  void registerNodeType(const std::string& id, ExtraArgs... args);
};

}  // namespace BT

// the real macro declares the plugin's registration function
#define BT_REGISTER_NODES(factory) \
  extern "C" void BT_RegisterNodesFromPlugin(BT::BehaviorTreeFactory& factory)

#endif  // RSIA_MODEL_BEHAVIORTREE_CPP_TREE_NODE_H
