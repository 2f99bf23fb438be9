// colcon-rsia model of <rclcpp_action/rclcpp_action.hpp> (ROS 2): written
// from the documented signatures (ros-api.md section 2.6).
#ifndef RSIA_MODEL_RCLCPP_ACTION_RCLCPP_ACTION_HPP
#define RSIA_MODEL_RCLCPP_ACTION_RCLCPP_ACTION_HPP

#include <rclcpp/rclcpp.hpp>

namespace rclcpp_action
{

enum class GoalResponse { REJECT = 1, ACCEPT_AND_EXECUTE = 2, ACCEPT_AND_DEFER = 3 };
enum class CancelResponse { REJECT = 1, ACCEPT = 2 };
using GoalUUID = std::array<uint8_t, 16>;

template<class ActionT>
class ServerGoalHandle
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(ServerGoalHandle)
  std::shared_ptr<const typename ActionT::Goal> get_goal() const;
  bool is_canceling() const;
  void publish_feedback(std::shared_ptr<typename ActionT::Feedback> feedback);
  void succeed(std::shared_ptr<typename ActionT::Result> result);
  void abort(std::shared_ptr<typename ActionT::Result> result);
  void canceled(std::shared_ptr<typename ActionT::Result> result);
};

template<class ActionT>
class ClientGoalHandle
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(ClientGoalHandle)
};

template<class ActionT>
class Server
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Server)
};

template<class ActionT>
class Client
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Client)
  using GoalHandle = ClientGoalHandle<ActionT>;
  template<class RepT, class RatioT>
  bool wait_for_action_server(std::chrono::duration<RepT, RatioT> timeout);
  template<class GoalT, class OptionsT>
  void async_send_goal(const GoalT & goal, const OptionsT & options);
  template<class GoalT>
  void async_send_goal(const GoalT & goal);
};

template<class ActionT, class NodeT, class GoalCallbackT,
  class CancelCallbackT, class AcceptedCallbackT>
typename Server<ActionT>::SharedPtr create_server(
  NodeT node, const std::string & name, GoalCallbackT handle_goal,
  CancelCallbackT handle_cancel, AcceptedCallbackT handle_accepted,
  const rclcpp::CallbackGroup::SharedPtr & group = nullptr);

template<class ActionT, class NodeT>
typename Client<ActionT>::SharedPtr create_client(
  NodeT node, const std::string & name,
  rclcpp::CallbackGroup::SharedPtr group = nullptr);

}  // namespace rclcpp_action

#endif  // RSIA_MODEL_RCLCPP_ACTION_RCLCPP_ACTION_HPP
