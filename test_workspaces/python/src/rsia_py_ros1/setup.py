# catkin_python_setup() reads this; never run it by hand.
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(
    packages=['rsia_py_ros1'],
    package_dir={'': 'src'},
))
