"""fusion: fuses camera images and IMU readings (message_filters, ROS 2 form).

RSIA patterns covered here:
- message_filters.Subscriber(node, Type, topic) feeding an ApproximateTimeSynchronizer
  stored in an attribute; the callback is registered on the synchroniser.
- A PUBLISH IN A HELPER REACHED FROM BOTH A TIMER AND A SUBSCRIPTION: publish_fused() runs
  in the synchroniser callback and in the 2 Hz timer callback -> fused_pose is dependent.
- A functools.partial callback (from functools import partial) and a service server.
"""

from functools import partial

from geometry_msgs.msg import PoseStamped
import message_filters
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Image
from sensor_msgs.msg import Imu
from std_msgs.msg import Float32
from std_srvs.srv import Trigger


class FusionNode(Node):

    def __init__(self):
        super().__init__('fusion')
        self.gain = 1.0
        self.last = PoseStamped()
        self.fused_pub = self.create_publisher(PoseStamped, 'fused_pose', 10)
        self.image_sub = message_filters.Subscriber(self, Image, 'camera/image')
        self.imu_sub = message_filters.Subscriber(self, Imu, 'imu')
        self.sync = message_filters.ApproximateTimeSynchronizer(
            [self.image_sub, self.imu_sub], 10, 0.05)
        self.sync.registerCallback(self.on_synced)
        self.create_subscription(Float32, 'gain', partial(self.on_param, 'gain'), 10)
        self.create_timer(0.5, self.republish)
        self.reset_service = self.create_service(Trigger, 'reset_fusion', self.on_reset)

    def on_synced(self, image, imu):
        self.last = PoseStamped()
        self.last.header = image.header
        self.publish_fused()

    def republish(self):
        self.publish_fused()

    def publish_fused(self):
        self.fused_pub.publish(self.last)

    def on_param(self, name, msg):
        setattr(self, name, msg.data)

    def on_reset(self, request, response):
        self.last = PoseStamped()
        response.success = True
        return response


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(FusionNode())
    rclpy.shutdown()
