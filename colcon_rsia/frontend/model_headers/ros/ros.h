// colcon-rsia model of <ros/ros.h>: everything a roscpp node includes.
#ifndef RSIA_MODEL_ROS_ROS_H
#define RSIA_MODEL_ROS_ROS_H

#include <ros/time.h>
#include <ros/rate.h>
#include <ros/console.h>
#include <ros/assert.h>
#include <ros/common.h>
#include <ros/types.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/single_subscriber_publisher.h>
#include <ros/service_server.h>
#include <ros/subscriber.h>
#include <ros/service.h>
#include <ros/init.h>
#include <ros/master.h>
#include <ros/this_node.h>
#include <ros/param.h>
#include <ros/topic.h>
#include <ros/names.h>

#endif  // RSIA_MODEL_ROS_ROS_H
