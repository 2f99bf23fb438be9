"""The base class of the sensor nodes (its subclasses live in other modules).

RSIA patterns covered here (with ultrasonic.py):
- A NODE CLASS SPREAD OVER TWO MODULES: the publishers and the timer are created here, in
  the base class; the subclass in ultrasonic.py subscribes and publishes on status_pub,
  which this base class owns.
- TIMER (pattern 2): range is published only in on_timer, every SENSOR_PERIOD_S (0.1 s, a
  constant of another module) -> independent, 10 Hz; the reading comes from read_range(),
  a hook the subclass overrides.
"""

from rclpy.node import Node
from sensor_msgs.msg import Range
from std_msgs.msg import String

from rsia_py_ros2.config import SENSOR_PERIOD_S


class SensorNodeBase(Node):

    def __init__(self, node_name):
        super().__init__(node_name)
        self.range_pub = self.create_publisher(Range, 'range', 10)
        self.status_pub = self.create_publisher(String, 'sensor_status', 10)
        self.timer = self.create_timer(SENSOR_PERIOD_S, self.on_timer)

    def on_timer(self):
        self.range_pub.publish(self.read_range())

    def read_range(self):
        raise NotImplementedError
