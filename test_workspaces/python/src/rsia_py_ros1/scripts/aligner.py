#!/usr/bin/env python3
"""aligner: an actionlib server that aligns the robot, fusing camera image and info.

RSIA patterns covered here:
- An actionlib.SimpleActionServer (an input, like a subscriber) whose execute callback runs
  a loop paced by a rospy.Rate created before it (ALIGN_RATE_HZ = 5): align_progress is
  published only inside the loop -> independent, rate_loop, 5 Hz, although the loop may be
  left early with a return; align_done after the loop -> dependent.
- message_filters (ROS 1 form Subscriber(topic, Type)) feeding an ApproximateTimeSynchronizer
  created and registered in one expression; fused_pose is published in its callback.
- tf2_ros.TransformListener: subscribes to /tf and /tf_static.
"""

import actionlib
from actionlib_tutorials.msg import FibonacciAction
from actionlib_tutorials.msg import FibonacciResult
from geometry_msgs.msg import PoseStamped
import message_filters
import rospy
from sensor_msgs.msg import CameraInfo
from sensor_msgs.msg import Image
from std_msgs.msg import Float32
from std_msgs.msg import String
import tf2_ros

ALIGN_RATE_HZ = 5


class Aligner(object):

    def __init__(self):
        self.progress_pub = rospy.Publisher('align_progress', Float32, queue_size=10)
        self.done_pub = rospy.Publisher('align_done', String, queue_size=1)
        self.fused_pub = rospy.Publisher('fused_pose', PoseStamped, queue_size=1)
        self.tf_buffer = tf2_ros.Buffer()
        self.tf_listener = tf2_ros.TransformListener(self.tf_buffer)
        image_sub = message_filters.Subscriber('camera/image', Image)
        info_sub = message_filters.Subscriber('camera/camera_info', CameraInfo)
        message_filters.ApproximateTimeSynchronizer(
            [image_sub, info_sub], 10, 0.05).registerCallback(self.on_pair)
        self.server = actionlib.SimpleActionServer(
            'align', FibonacciAction, execute_cb=self.execute, auto_start=False)
        self.server.start()

    def on_pair(self, image, info):
        pose = PoseStamped()
        pose.header = image.header
        self.fused_pub.publish(pose)

    def execute(self, goal):
        rate = rospy.Rate(ALIGN_RATE_HZ)
        for step in range(goal.order):
            if self.server.is_preempt_requested():
                self.server.set_preempted()
                return
            self.progress_pub.publish(Float32(float(step)))
            rate.sleep()
        self.done_pub.publish(String('aligned'))
        self.server.set_succeeded(FibonacciResult())


def main():
    rospy.init_node('aligner')
    Aligner()
    rospy.spin()


if __name__ == '__main__':
    main()
