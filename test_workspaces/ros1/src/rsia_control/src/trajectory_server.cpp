// trajectory_server: executes a (simulated) trajectory of N steps as an action.
//
// RSIA patterns covered here:
// - actionlib::SimpleActionServer with an execute callback (boost::bind). An action server
//   counts as a subscriber, so pattern 1 does not apply.
// - Inside the execute callback, a loop paced by a ros::Rate declared just before it: the
//   path execute callback -> loop -> publish passes through a Rate-paced loop -> rate_loop.
// - A publish in the same callback but OUTSIDE the loop -> dependent (one per goal).
#include <algorithm>
#include <string>

#include <actionlib/TestAction.h>
#include <actionlib/server/simple_action_server.h>
#include <boost/bind/bind.hpp>
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <std_msgs/String.h>

using namespace boost::placeholders;

class TrajectoryServer
{
public:
  explicit TrajectoryServer(ros::NodeHandle& nh)
    // API: actionlib::SimpleActionServer(nh, name, execute callback, auto_start).
    : server_(nh, "execute_trajectory", boost::bind(&TrajectoryServer::execute, this, _1), false)
  {
    progress_pub_ = nh.advertise<std_msgs::Float64>("trajectory_progress", 10);
    done_pub_ = nh.advertise<std_msgs::String>("trajectory_done", 10);
    server_.start();
  }

  // Execute callback: runs once per accepted goal.
  void execute(const actionlib::TestGoalConstPtr& goal)
  {
    const int steps = std::max(1, static_cast<int>(goal->goal));
    actionlib::TestFeedback feedback;
    ros::Rate step_rate(10.0);
    bool preempted = false;
    for (int step = 1; step <= steps; ++step)
    {
      if (server_.isPreemptRequested() || !ros::ok())
      {
        preempted = true;
        break;
      }
      std_msgs::Float64 progress;
      progress.data = static_cast<double>(step) / steps;
      // EXPECT trajectory_progress: independent, rate_loop (the only path runs through the
      // loop paced by step_rate, declared before the loop), rate_hz 10.0.
      progress_pub_.publish(progress);
      feedback.feedback = step;
      server_.publishFeedback(feedback);
      step_rate.sleep();
    }

    if (preempted)
    {
      server_.setPreempted();
      publishDone("preempted");
      return;
    }
    actionlib::TestResult result;
    result.result = steps;
    server_.setSucceeded(result);
    publishDone("succeeded");
  }

private:
  void publishDone(const std::string& outcome)
  {
    std_msgs::String msg;
    msg.data = outcome;
    // EXPECT trajectory_done: dependent, none (called from the action execute callback after
    // the Rate loop, once per goal).
    done_pub_.publish(msg);
  }

  actionlib::SimpleActionServer<actionlib::TestAction> server_;
  ros::Publisher progress_pub_;
  ros::Publisher done_pub_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "trajectory_server");
  ros::NodeHandle nh;
  TrajectoryServer server(nh);
  ros::spin();
  return 0;
}
