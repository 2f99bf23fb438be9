#ifndef RSIA_HOSTED_NODELETS_RELAY_BASE_H
#define RSIA_HOSTED_NODELETS_RELAY_BASE_H

#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <tf/transform_listener.h>

namespace rsia_hosted_nodelets
{

// What every relay has: its private handle and a tf listener.
class RelayBase : public nodelet::Nodelet
{
protected:
  void onInit() override;

  boost::shared_ptr<ros::NodeHandle> pnh_;
  tf::TransformListener tf_listener_;
};

}  // namespace rsia_hosted_nodelets

#endif
