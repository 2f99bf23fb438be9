// Service clients only: a client is no subscription, neither is the
// parameter callback nor the /parameter_events subscription rclcpp makes by
// itself, so the node has no subscribers and map_copy is independent by
// pattern 1, although it is published from the response callback.
#include <chrono>
#include <functional>
#include <memory>
#include <vector>

#include "rclcpp/rclcpp.hpp"
#include "nav_msgs/msg/occupancy_grid.hpp"
#include "nav_msgs/srv/get_map.hpp"
#include "rcl_interfaces/msg/set_parameters_result.hpp"
#include "std_srvs/srv/trigger.hpp"

using namespace std::chrono_literals;

class MapClient : public rclcpp::Node
{
public:
  MapClient()
  : Node("map_client")
  {
    map_client_ = create_client<nav_msgs::srv::GetMap>("map_server/map");
    reset_client_ = this->create_client<std_srvs::srv::Trigger>(
      "/reset_odometry", rclcpp::ServicesQoS());
    map_pub_ = create_publisher<nav_msgs::msg::OccupancyGrid>(
      "map_copy", rclcpp::QoS(1).transient_local());
    timer_ = create_wall_timer(5s, std::bind(&MapClient::requestMap, this));
    param_handle_ = add_on_set_parameters_callback(
      std::bind(&MapClient::onParameters, this, std::placeholders::_1));
  }

private:
  void requestMap()
  {
    if (!map_client_->wait_for_service(1s)) {
      RCLCPP_WARN(get_logger(), "map service not available");
      return;
    }
    auto request = std::make_shared<nav_msgs::srv::GetMap::Request>();
    map_client_->async_send_request(
      request,
      [this](rclcpp::Client<nav_msgs::srv::GetMap>::SharedFuture future) {
        map_pub_->publish(future.get()->map);
      });
  }

  rcl_interfaces::msg::SetParametersResult onParameters(
    const std::vector<rclcpp::Parameter> & parameters)
  {
    rcl_interfaces::msg::SetParametersResult result;
    result.successful = true;
    for (const auto & parameter : parameters) {
      if (parameter.get_name() == "reset_odometry" && parameter.as_bool()) {
        reset_client_->async_send_request(
          std::make_shared<std_srvs::srv::Trigger::Request>());
      }
    }
    return result;
  }

  rclcpp::Client<nav_msgs::srv::GetMap>::SharedPtr map_client_;
  rclcpp::Client<std_srvs::srv::Trigger>::SharedPtr reset_client_;
  rclcpp::Publisher<nav_msgs::msg::OccupancyGrid>::SharedPtr map_pub_;
  rclcpp::TimerBase::SharedPtr timer_;
  OnSetParametersCallbackHandle::SharedPtr param_handle_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<MapClient>());
  rclcpp::shutdown();
  return 0;
}
