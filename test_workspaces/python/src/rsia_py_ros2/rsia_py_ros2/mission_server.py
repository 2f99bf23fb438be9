"""mission_server: an rclpy action server reporting its progress at a fixed rate.

RSIA patterns covered here:
- An rclpy.action.ActionServer (an input): its execute callback runs a loop paced by
  self.create_rate(PROGRESS_HZ) created before the loop -> mission_progress independent,
  rate_loop, 4 Hz; mission_result after the loop -> dependent.
- An rclpy.action.ActionClient and a service client (neither is an input).
"""

from action_tutorials_interfaces.action import Fibonacci
import rclpy
from rclpy.action import ActionClient
from rclpy.action import ActionServer
from rclpy.action import GoalResponse
from rclpy.node import Node
from std_msgs.msg import Float32
from std_msgs.msg import String
from std_srvs.srv import Trigger

PROGRESS_HZ = 4


class MissionServer(Node):

    def __init__(self):
        super().__init__('mission_server')
        self.progress_pub = self.create_publisher(Float32, 'mission_progress', 10)
        self.result_pub = self.create_publisher(String, 'mission_result', 10)
        self.server = ActionServer(
            self, Fibonacci, 'mission', execute_callback=self.execute,
            goal_callback=self.on_goal)
        self.dock_client = ActionClient(self, Fibonacci, 'dock')
        self.lights_client = self.create_client(Trigger, 'lights_on')

    def on_goal(self, goal_request):
        return GoalResponse.ACCEPT

    def execute(self, goal_handle):
        rate = self.create_rate(PROGRESS_HZ)
        for step in range(goal_handle.request.order):
            self.progress_pub.publish(Float32(data=float(step)))
            rate.sleep()
        self.result_pub.publish(String(data='done'))
        goal_handle.succeed()
        return Fibonacci.Result()


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(MissionServer())
