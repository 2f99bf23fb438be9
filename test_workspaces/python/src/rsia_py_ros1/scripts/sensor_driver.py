#!/usr/bin/env python3
"""sensor_driver: publishes a range reading and the sensor frame; subscribes to nothing.

RSIA patterns covered here:
- NO SUBSCRIBERS (pattern 1): the node has no subscriber, service or action server, so
  every publisher is independent (no_subscribers), whatever paces it.
- The whole node is the module body (no main function): the body is the main root.
- A rospy.Rate loop at a rate imported from the package's own module (10 Hz); a
  tf2_ros.TransformBroadcaster used in a rospy.Timer callback; a publish through a
  helper of another module of the package (publish_status).
"""

import rospy
from geometry_msgs.msg import TransformStamped
from sensor_msgs.msg import Range
from std_msgs.msg import String
import tf2_ros

from rsia_py_ros1.util import DEFAULT_RATE_HZ
from rsia_py_ros1.util import publish_status

rospy.init_node('sensor_driver')
range_pub = rospy.Publisher('range', Range, queue_size=10)
status_pub = rospy.Publisher('~status', String, queue_size=1, latch=True)
broadcaster = tf2_ros.TransformBroadcaster()


def send_frame(event):
    frame = TransformStamped()
    frame.header.stamp = rospy.Time.now()
    frame.header.frame_id = 'base_link'
    frame.child_frame_id = 'range_sensor'
    frame.transform.rotation.w = 1.0
    broadcaster.sendTransform(frame)


rospy.Timer(rospy.Duration(0.5), send_frame)
publish_status(status_pub, 'started')

rate = rospy.Rate(DEFAULT_RATE_HZ)
while not rospy.is_shutdown():
    reading = Range()
    reading.header.stamp = rospy.Time.now()
    reading.range = 1.0
    range_pub.publish(reading)
    rate.sleep()
