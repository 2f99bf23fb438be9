// A model plugin: gazebo_ros::Node::Get(sdf) makes its node, named after
// the <plugin name="..."> of the SDF, in the SDF's <ros><namespace>.
#include <gazebo/common/Events.hh>
#include <gazebo/common/Plugin.hh>
#include <gazebo/physics/Model.hh>
#include <gazebo_ros/node.hpp>
#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/joint_state.hpp>
#include <std_msgs/msg/float64.hpp>
#include <std_msgs/msg/string.hpp>

#include <memory>

namespace rsia_gazebo_ros2_plugins
{

class JointPublisher : public gazebo::ModelPlugin
{
public:
  void Load(gazebo::physics::ModelPtr model, sdf::ElementPtr sdf) override
  {
    node_ = gazebo_ros::Node::Get(sdf);
    joint_pub_ = node_->create_publisher<sensor_msgs::msg::JointState>("joint_states", 10);
    status_pub_ = node_->create_publisher<std_msgs::msg::String>("~/status", 10);
    target_sub_ = node_->create_subscription<std_msgs::msg::Float64>(
      "target", 10,
      std::bind(&JointPublisher::OnTarget, this, std::placeholders::_1));
    update_connection_ = gazebo::event::Events::ConnectWorldUpdateBegin(
      std::bind(&JointPublisher::OnUpdate, this, std::placeholders::_1));
  }

private:
  void OnUpdate(const gazebo::common::UpdateInfo & info)
  {
    sensor_msgs::msg::JointState state;
    joint_pub_->publish(state);
  }

  void OnTarget(const std_msgs::msg::Float64::SharedPtr target)
  {
    std_msgs::msg::String status;
    status.data = std::to_string(target->data);
    status_pub_->publish(status);
  }

  gazebo_ros::Node::SharedPtr node_;
  rclcpp::Publisher<sensor_msgs::msg::JointState>::SharedPtr joint_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_pub_;
  rclcpp::Subscription<std_msgs::msg::Float64>::SharedPtr target_sub_;
  gazebo::event::ConnectionPtr update_connection_;
};

GZ_REGISTER_MODEL_PLUGIN(JointPublisher)

}  // namespace rsia_gazebo_ros2_plugins
