"""Helpers shared by the rsia_py_ros1 scripts."""

from std_msgs.msg import String

# a module-level constant: rates built from it are known (10 Hz)
DEFAULT_RATE_HZ = 10.0


def status(text):
    msg = String()
    msg.data = text
    return msg


def publish_status(publisher, text):
    # Publishes through a parameter: the publish site stands for every publisher passed in
    # (sensor_driver's ~status, lidar_filter's filter_state).
    publisher.publish(status(text))
