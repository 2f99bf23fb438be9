"""Constants shared by the rsia_py_ros2 nodes."""

PLAN_RATE_HZ = 2.0
SENSOR_PERIOD_S = 0.1
