"""Helpers shared by the rsia_py_ros1 scripts."""
