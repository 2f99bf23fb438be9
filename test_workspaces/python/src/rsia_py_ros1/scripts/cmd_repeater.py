#!/usr/bin/env python3
"""cmd_repeater: repeats the last velocity command; reports it is alive.

RSIA patterns covered here:
- A LOOP PACED BY time.sleep() in a node that subscribes: a plain sleep is not adaptive, so
  cmd_vel_out (published in that loop) is dependent.
- A rospy.Rate CREATED INSIDE THE LOOP it paces never adapts -> repeater_state is dependent.
  Its loop runs in a function started as a thread target (a function reference, not a call).
- rospy.wait_for_message: a one-shot subscription, an input of the node (callback null).
"""

import threading
import time

import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import Empty
from std_msgs.msg import String


class Repeater:

    def __init__(self):
        self.last = Twist()
        self.cmd_pub = rospy.Publisher('cmd_vel_out', Twist, queue_size=1)
        self.sub = rospy.Subscriber('cmd_vel_in', Twist, self.on_cmd)

    def on_cmd(self, msg):
        self.last = msg

    def run(self):
        rospy.wait_for_message('robot_ready', Empty)
        while not rospy.is_shutdown():
            self.cmd_pub.publish(self.last)
            time.sleep(0.1)


def report_loop():
    state_pub = rospy.Publisher('repeater_state', String, queue_size=1)
    while not rospy.is_shutdown():
        rate = rospy.Rate(1)
        state_pub.publish(String('alive'))
        rate.sleep()


if __name__ == '__main__':
    rospy.init_node('cmd_repeater')
    threading.Thread(target=report_loop).start()
    Repeater().run()
