"""pose_broadcaster: broadcasts the odometry frame on /tf from a timer.

RSIA patterns covered here:
- A tf2_ros.TransformBroadcaster whose sendTransform runs only in a timer callback every
  BROADCAST_PERIOD_S = 0.05 s -> /tf independent, timer, 20 Hz, although the node
  subscribes (odom, with a lambda callback) and listens to tf.
- A tf2_ros.StaticTransformBroadcaster sent once from the constructor (main root) ->
  /tf_static dependent.
- tf2_ros.TransformListener imported from its inner module (tf2_ros.transform_listener).
"""

from geometry_msgs.msg import TransformStamped
from nav_msgs.msg import Odometry
import rclpy
from rclpy.node import Node
from tf2_ros import StaticTransformBroadcaster
from tf2_ros import TransformBroadcaster
from tf2_ros.buffer import Buffer
from tf2_ros.transform_listener import TransformListener

BROADCAST_PERIOD_S = 0.05


class PoseBroadcaster(Node):

    def __init__(self):
        super().__init__('pose_broadcaster')
        self.last_odom = None
        self.broadcaster = TransformBroadcaster(self)
        self.static_broadcaster = StaticTransformBroadcaster(self)
        self.tf_buffer = Buffer()
        self.tf_listener = TransformListener(self.tf_buffer, self)
        self.create_subscription(
            Odometry, 'odom', lambda msg: setattr(self, 'last_odom', msg), 10)
        self.create_timer(BROADCAST_PERIOD_S, self.broadcast)
        self.static_broadcaster.sendTransform(self.mounting_transform())

    def mounting_transform(self):
        mount = TransformStamped()
        mount.header.frame_id = 'base_link'
        mount.child_frame_id = 'lidar'
        mount.transform.rotation.w = 1.0
        return mount

    def broadcast(self):
        if self.last_odom is None:
            return
        frame = TransformStamped()
        frame.header = self.last_odom.header
        frame.child_frame_id = 'base_link'
        frame.transform.translation.x = self.last_odom.pose.pose.position.x
        frame.transform.translation.y = self.last_odom.pose.pose.position.y
        frame.transform.rotation = self.last_odom.pose.pose.orientation
        self.broadcaster.sendTransform(frame)


def main():
    rclpy.init()
    rclpy.spin(PoseBroadcaster())
