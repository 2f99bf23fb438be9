// colcon-rsia model of <rclcpp_action/rclcpp_action.hpp> (ROS 2): written
// from the documented signatures (the rclcpp_action API documentation).
#ifndef RSIA_MODEL_RCLCPP_ACTION_RCLCPP_ACTION_HPP
#define RSIA_MODEL_RCLCPP_ACTION_RCLCPP_ACTION_HPP

#include <chrono>
#include <functional>
#include <future>
#include <memory>
#include <string>

#include <rclcpp/rclcpp.hpp>
#include <action_msgs/srv/cancel_goal.hpp>

struct rcl_action_server_options_t
{
  std::size_t result_timeout_ns;
};
struct rcl_action_client_options_t
{
  std::size_t feedback_topic_qos_depth;
};
rcl_action_server_options_t rcl_action_server_get_default_options(void);
rcl_action_client_options_t rcl_action_client_get_default_options(void);

namespace rclcpp_action
{

enum class GoalResponse { REJECT = 1, ACCEPT_AND_EXECUTE = 2, ACCEPT_AND_DEFER = 3 };
enum class CancelResponse { REJECT = 1, ACCEPT = 2 };
enum class ResultCode : int8_t { UNKNOWN = 0, SUCCEEDED = 4, CANCELED = 5, ABORTED = 6 };
using GoalUUID = std::array<uint8_t, 16>;

template<class ActionT>
class ServerGoalHandle
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(ServerGoalHandle)
  const GoalUUID & get_goal_id() const;
  std::shared_ptr<const typename ActionT::Goal> get_goal() const;
  bool is_canceling() const;
  bool is_active() const;
  bool is_executing() const;
  void execute();
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
  struct WrappedResult
  {
    GoalUUID goal_id;
    ResultCode code;
    typename ActionT::Result::SharedPtr result;
  };
  using Feedback = typename ActionT::Feedback;
  using Result = typename ActionT::Result;
  using FeedbackCallback = std::function<void (
        typename ClientGoalHandle<ActionT>::SharedPtr,
        const std::shared_ptr<const Feedback>)>;
  using ResultCallback = std::function<void (const WrappedResult & result)>;

  const GoalUUID & get_goal_id() const;
  rclcpp::Time get_goal_stamp() const;
  int8_t get_status();
  bool is_feedback_aware();
  bool is_result_aware();
};

template<class ActionT>
class Server
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Server)
  using GoalCallback = std::function<GoalResponse(
        const GoalUUID &, std::shared_ptr<const typename ActionT::Goal>)>;
  using CancelCallback = std::function<CancelResponse(
        std::shared_ptr<ServerGoalHandle<ActionT>>)>;
  using AcceptedCallback = std::function<void (std::shared_ptr<ServerGoalHandle<ActionT>>)>;
};

template<class ActionT>
class Client
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Client)
  using Goal = typename ActionT::Goal;
  using Feedback = typename ActionT::Feedback;
  using GoalHandle = ClientGoalHandle<ActionT>;
  using WrappedResult = typename GoalHandle::WrappedResult;
  using GoalResponseCallback = std::function<void (typename GoalHandle::SharedPtr)>;
  using FeedbackCallback = typename GoalHandle::FeedbackCallback;
  using ResultCallback = typename GoalHandle::ResultCallback;
  using CancelRequest = action_msgs::srv::CancelGoal::Request;
  using CancelResponse = action_msgs::srv::CancelGoal::Response;
  using CancelCallback = std::function<void (typename CancelResponse::SharedPtr)>;

  struct SendGoalOptions
  {
    SendGoalOptions();
    GoalResponseCallback goal_response_callback;
    FeedbackCallback feedback_callback;
    ResultCallback result_callback;
  };

  bool action_server_is_ready() const;
  template<class RepT = int64_t, class RatioT = std::milli>
  bool wait_for_action_server(
    std::chrono::duration<RepT, RatioT> timeout = std::chrono::duration<RepT, RatioT>(-1));
  std::shared_future<typename GoalHandle::SharedPtr> async_send_goal(
    const Goal & goal, const SendGoalOptions & options = SendGoalOptions());
  std::shared_future<WrappedResult> async_get_result(
    typename GoalHandle::SharedPtr goal_handle, ResultCallback result_callback = nullptr);
  std::shared_future<typename CancelResponse::SharedPtr> async_cancel_goal(
    typename GoalHandle::SharedPtr goal_handle, CancelCallback cancel_callback = nullptr);
  std::shared_future<typename CancelResponse::SharedPtr> async_cancel_all_goals(
    CancelCallback cancel_callback = nullptr);
};

// create_server<ActionT>(node, name, handle_goal, handle_cancel,
// handle_accepted, options, group): the callbacks are std::function types
// in the real header; deduced here, so that lambdas, std::bind expressions
// and functions all resolve to this declaration
template<class ActionT, class NodeT, class GoalCallbackT,
  class CancelCallbackT, class AcceptedCallbackT>
typename Server<ActionT>::SharedPtr create_server(
  NodeT node, const std::string & name, GoalCallbackT handle_goal,
  CancelCallbackT handle_cancel, AcceptedCallbackT handle_accepted,
  const rcl_action_server_options_t & options = rcl_action_server_get_default_options(),
  rclcpp::CallbackGroup::SharedPtr group = nullptr);

template<class ActionT, class NodeT>
typename Client<ActionT>::SharedPtr create_client(
  NodeT node, const std::string & name,
  rclcpp::CallbackGroup::SharedPtr group = nullptr,
  const rcl_action_client_options_t & options = rcl_action_client_get_default_options());

}  // namespace rclcpp_action

#endif  // RSIA_MODEL_RCLCPP_ACTION_RCLCPP_ACTION_HPP
