from setuptools import find_packages
from setuptools import setup

package_name = 'rsia_py_ros2'

setup(
    name=package_name,
    version='0.0.1',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='rsia developers',
    maintainer_email='dev@example.com',
    description='colcon-rsia test package: rclpy nodes',
    license='BSD',
    tests_require=['pytest'],
    entry_points={
        'console_scripts': [
            'ultrasonic = rsia_py_ros2.ultrasonic:main',
            f'pose_broadcaster = {package_name}.pose_broadcaster:main',
            'fusion = rsia_py_ros2.fusion_node:main',
            'planner = ' + package_name + '.planner:main',
            'mission_server = rsia_py_ros2.mission_server:main',
            'heartbeat = rsia_py_ros2.heartbeat:run',
        ],
    },
)
