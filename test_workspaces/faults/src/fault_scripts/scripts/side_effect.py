#!/usr/bin/env python3
"""A node whose top level writes a marker file: analysing it must not."""
import os

import rospy
from std_msgs.msg import String

with open(os.path.join(os.getcwd(), 'RSIA_SIDE_EFFECT_MARKER'), 'w') as marker:
    marker.write('this module was executed\n')


def main():
    rospy.init_node('side_effect')
    pub = rospy.Publisher('marker', String, queue_size=1)
    rate = rospy.Rate(1)
    while not rospy.is_shutdown():
        pub.publish(String())
        rate.sleep()


if __name__ == '__main__':
    main()
