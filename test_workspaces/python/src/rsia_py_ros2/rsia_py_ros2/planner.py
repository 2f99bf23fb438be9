"""planner: plans towards the latest goal at a fixed rate (no node class).

RSIA patterns covered here:
- RATE LOOP (pattern 3) in main with node.create_rate(config.PLAN_RATE_HZ): 2 Hz, a constant
  of another module read as a module attribute; executor spinning in a thread.
- A LOOP PACED BY time.sleep() in a function started as a thread target (a reference to a
  nested function, not a call) in a node that subscribes -> planner_debug is dependent.
- A nested function as subscriber callback (named main.on_goal).
"""

import threading
import time

from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Path
import rclpy
from std_msgs.msg import String

from rsia_py_ros2 import config


def main():
    rclpy.init()
    node = rclpy.create_node('planner')
    goal = {'pose': None}

    def on_goal(msg):
        goal['pose'] = msg

    node.create_subscription(PoseStamped, 'goal', on_goal, 10)
    plan_pub = node.create_publisher(Path, 'plan', 10)
    debug_pub = node.create_publisher(String, 'planner_debug', 10)

    def debug_loop():
        while rclpy.ok():
            debug_pub.publish(String(data='planning'))
            time.sleep(1.0)

    threading.Thread(target=rclpy.spin, args=(node,), daemon=True).start()
    threading.Thread(target=debug_loop, daemon=True).start()
    rate = node.create_rate(config.PLAN_RATE_HZ)
    while rclpy.ok():
        if goal['pose'] is not None:
            plan = Path()
            plan.poses = [goal['pose']]
            plan_pub.publish(plan)
        rate.sleep()
