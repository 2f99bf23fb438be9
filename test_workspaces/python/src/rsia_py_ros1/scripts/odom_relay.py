#!/usr/bin/env python3
"""odom_relay: republishes odometry as a pose; a heartbeat; a reset service.

RSIA patterns covered here:
- A PUBLISH IN A HELPER REACHED FROM BOTH A TIMER AND A SUBSCRIPTION: publish_pose() runs
  in on_timer (timer root) and in on_odom (subscriber root) -> pose is dependent.
- TIMER (pattern 2): heartbeat is published only in the rospy.Timer callback, at
  1.0 / HEARTBEAT_HZ s (module constant) -> independent, 5 Hz.
- A publish in a rospy.Service handler -> dependent.
"""

import rospy
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Odometry
from std_msgs.msg import Empty
from std_msgs.msg import Int32
from std_srvs.srv import Empty as EmptyService
from std_srvs.srv import EmptyResponse

HEARTBEAT_HZ = 5


class OdomRelay(object):

    def __init__(self):
        self.last = None
        self.resets = 0
        self.pose_pub = rospy.Publisher('pose', PoseStamped, queue_size=10)
        self.heartbeat_pub = rospy.Publisher('heartbeat', Empty, queue_size=1)
        self.resets_pub = rospy.Publisher('reset_count', Int32, queue_size=1)
        rospy.Subscriber('odom', Odometry, self.on_odom, queue_size=1)
        rospy.Service('reset_relay', EmptyService, self.on_reset)
        self.timer = rospy.Timer(rospy.Duration(1.0 / HEARTBEAT_HZ), self.on_timer)

    def on_odom(self, msg):
        self.last = msg
        self.publish_pose()

    def on_timer(self, event):
        self.heartbeat_pub.publish(Empty())
        if self.last is not None:
            self.publish_pose()

    def publish_pose(self):
        pose = PoseStamped()
        pose.header = self.last.header
        pose.pose = self.last.pose.pose
        self.pose_pub.publish(pose)

    def on_reset(self, request):
        self.resets += 1
        self.resets_pub.publish(Int32(self.resets))
        return EmptyResponse()


def main():
    rospy.init_node('odom_relay')
    OdomRelay()
    rospy.spin()


if __name__ == '__main__':
    main()
