"""heartbeat: announces that the robot is alive (entry point function `run`).

RSIA patterns covered here:
- NO SUBSCRIBERS (pattern 1): a timer and a service client only (a client is no input)
  -> every publisher independent, no_subscribers.
"""

import rclpy
from rclpy.node import Node
from std_msgs.msg import Empty
from std_msgs.msg import String
from std_srvs.srv import Trigger


class Heartbeat(Node):

    def __init__(self):
        super().__init__('heartbeat')
        self.beat_pub = self.create_publisher(Empty, 'heartbeat', 1)
        self.version_pub = self.create_publisher(String, 'version', 1)
        self.beat_timer = self.create_timer(1.0, self.beat)
        self.version_client = self.create_client(Trigger, 'get_version')

    def beat(self):
        self.beat_pub.publish(Empty())
        self.version_pub.publish(String(data='1.0'))


def run(args=None):
    rclpy.init(args=args)
    rclpy.spin(Heartbeat())
