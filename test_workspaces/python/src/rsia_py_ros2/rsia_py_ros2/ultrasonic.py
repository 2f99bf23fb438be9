"""ultrasonic: a sensor node built on SensorNodeBase (base_sensor.py).

RSIA patterns covered here:
- A publish on a publisher created by the base class in another module (status_pub) from a
  subscription callback -> sensor_status is dependent.
- read_range() overrides the base class's hook, called from the base's timer callback.
"""

import rclpy
from sensor_msgs.msg import Range
from std_msgs.msg import String

from .base_sensor import SensorNodeBase


class UltrasonicNode(SensorNodeBase):

    def __init__(self):
        super().__init__('ultrasonic')
        self.command_sub = self.create_subscription(
            String, 'sensor_command', self.on_command, 10)

    def on_command(self, msg):
        self.status_pub.publish(String(data='ack ' + msg.data))

    def read_range(self):
        reading = Range()
        reading.range = 0.5
        return reading


def main(args=None):
    rclpy.init(args=args)
    node = UltrasonicNode()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()
