# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Cost of the analysis, measured in one run on a synthetic workspace.

Generates a catkin workspace of N packages with realistic ROS 1 nodes (a
Rate-paced driver, a relay, a timer-driven aggregator per package, chained
across packages) and measures: a clean ``colcon build`` without the
handler (before the others and again after them: the faster of the two
is the reference), with it in model and in exact header mode, a no-change
rebuild with it; ``impact`` and ``impact --all`` on a synthetic 2,000-node system
graph; the peak memory of analysing the workspace. Ends with one line:

RESULT overhead_model=<ratio> overhead_exact=<ratio> nochange_analysis_s=<s>
nochange_wait_s=<s> impact_ms=<ms> all_s=<s> peak_mb=<mb>

``nochange_analysis_s`` is the analysis's own time over the packages of a
no-change rebuild (it runs beside the build); ``nochange_wait_s`` how long
that build waited for it after its last job.

Usage: python3 bench/run.py [--packages N] [--root DIR]
"""

import argparse
import json
import os
from pathlib import Path
import random
import re
import subprocess
import sys
import time

from colcon_rsia.summary.kinds import DEPENDENT
from colcon_rsia.summary.kinds import INDEPENDENT
from colcon_rsia.summary.nodes import LabelledPublisher
from colcon_rsia.summary.nodes import Node
from colcon_rsia.summary.nodes import NodeSubscriber
from colcon_rsia.summary.package_summary import PackageSummary
from colcon_rsia.system.graph import build_graph
from colcon_rsia.system.impact import impact_all
from colcon_rsia.system.impact import rate_impact
from colcon_rsia.system.impact import traditional_impact
from common import CMAKE_ARGS
from common import colcon
from common import colcon_build

PACKAGE_XML = """<?xml version="1.0"?>
<package format="2">
  <name>{name}</name><version>0.0.1</version>
  <description>synthetic benchmark package</description>
  <maintainer email="dev@example.com">bench</maintainer>
  <license>Apache-2.0</license>
  <buildtool_depend>catkin</buildtool_depend>
  <depend>roscpp</depend><depend>std_msgs</depend>
  <depend>sensor_msgs</depend><depend>tf2_ros</depend>
</package>
"""
CMAKELISTS = """cmake_minimum_required(VERSION 3.5)
project({name})
find_package(catkin REQUIRED COMPONENTS roscpp std_msgs sensor_msgs tf2_ros)
catkin_package()
include_directories(${{catkin_INCLUDE_DIRS}})
foreach(node driver relay aggregator)
  add_executable(${{node}} src/${{node}}.cpp)
  target_link_libraries(${{node}} ${{catkin_LIBRARIES}})
endforeach()
"""
DRIVER = """#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_ros/transform_broadcaster.h>
#include <geometry_msgs/TransformStamped.h>
constexpr double kRateHz = 20.0;
class Driver {{
 public:
  explicit Driver(ros::NodeHandle& nh)
      : pub_(nh.advertise<sensor_msgs::LaserScan>("{p}/scan", 5)) {{}}
  void spinOnce() {{
    sensor_msgs::LaserScan scan;
    scan.header.stamp = ros::Time::now();
    pub_.publish(scan);
    geometry_msgs::TransformStamped t;
    t.header.stamp = scan.header.stamp;
    broadcaster_.sendTransform(t);
  }}
 private:
  ros::Publisher pub_;
  tf2_ros::TransformBroadcaster broadcaster_;
}};
int main(int argc, char** argv) {{
  ros::init(argc, argv, "driver");
  ros::NodeHandle nh;
  Driver driver(nh);
  ros::Rate rate(kRateHz);
  while (ros::ok()) {{ driver.spinOnce(); ros::spinOnce(); rate.sleep(); }}
}}
"""
RELAY = """#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Float32.h>
ros::Publisher g_filtered, g_range;
void onScan(const sensor_msgs::LaserScan::ConstPtr& msg) {{
  sensor_msgs::LaserScan out = *msg;
  g_filtered.publish(out);
  std_msgs::Float32 range;
  range.data = msg->ranges.empty() ? 0.0f : msg->ranges[0];
  g_range.publish(range);
}}
int main(int argc, char** argv) {{
  ros::init(argc, argv, "relay");
  ros::NodeHandle nh;
  g_filtered = nh.advertise<sensor_msgs::LaserScan>("{p}/scan_filtered", 5);
  g_range = nh.advertise<std_msgs::Float32>("{p}/range", 5);
  ros::Subscriber sub = nh.subscribe("{p}/scan", 5, onScan);
  ros::spin();
}}
"""
AGGREGATOR = """#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Float32.h>
#include <std_msgs/String.h>
class Aggregator {{
 public:
  explicit Aggregator(ros::NodeHandle& nh) {{
    pub_ = nh.advertise<std_msgs::String>("{p}/status", 1);
    sub_ = nh.subscribe("{p}/scan_filtered", 5, &Aggregator::onScan, this);
    prev_ = nh.subscribe("{prev}/range", 5, &Aggregator::onRange, this);
    timer_ = nh.createTimer(ros::Duration(0.5), &Aggregator::onTimer, this);
  }}
 private:
  void onScan(const sensor_msgs::LaserScan::ConstPtr&) {{ ++count_; }}
  void onRange(const std_msgs::Float32::ConstPtr& msg) {{ last_ = msg->data; }}
  void onTimer(const ros::TimerEvent&) {{
    std_msgs::String s;
    s.data = std::to_string(count_) + " " + std::to_string(last_);
    pub_.publish(s);
  }}
  ros::Publisher pub_;
  ros::Subscriber sub_, prev_;
  ros::Timer timer_;
  int count_ = 0;
  float last_ = 0;
}};
int main(int argc, char** argv) {{
  ros::init(argc, argv, "aggregator");
  ros::NodeHandle nh;
  Aggregator aggregator(nh);
  ros::spin();
}}
"""


def generate_workspace(src, packages):
    for index in range(packages):
        name = f'bench_pkg_{index}'
        previous = f'bench_pkg_{(index - 1) % packages}'
        package = src / name
        (package / 'src').mkdir(parents=True, exist_ok=True)
        (package / 'package.xml').write_text(PACKAGE_XML.format(name=name))
        (package / 'CMakeLists.txt').write_text(CMAKELISTS.format(name=name))
        for file, template in (('driver', DRIVER), ('relay', RELAY),
                               ('aggregator', AGGREGATOR)):
            (package / 'src' / f'{file}.cpp').write_text(
                template.format(p=name, prev=previous))


def analysis_seconds(output):
    """The packages' own analysis time the handler reports."""
    match = re.search(r'rsia: analysed .*: ([0-9.]+)s of analysis', output)
    return float(match.group(1)) if match else float('nan')


def waited_seconds(output):
    """How long the build waited for the analysis after its last job."""
    match = re.search(r'the build waited ([0-9.]+)s for it', output)
    return float(match.group(1)) if match else float('nan')


def synthetic_system(nodes, seed=1):
    """A random robot-like system graph of `nodes` nodes.

    Nodes sit in layers (sensors, perception, planning, control, drivers
    feeding back odometry); each node subscribes to 1-3 topics of the
    layer before it (or of feedback topics) and publishes 1-3 topics, a
    third of them independent (timers, rate loops).
    """
    rng = random.Random(seed)
    layers = 6
    per_layer = max(1, nodes // layers)
    topics_by_layer = [[] for _ in range(layers)]
    summary_nodes = []
    for index in range(nodes):
        layer = min(index // per_layer, layers - 1)
        publishers = []
        for number in range(rng.randint(1, 3)):
            topic = f'/l{layer}/n{index}/t{number}'
            topics_by_layer[layer].append(topic)
            publishers.append(LabelledPublisher(
                topic=topic, topic_is_literal=True, msg_type='m', api='a',
                handle='h', namespace='', location='f:1',
                label=rng.choice([INDEPENDENT, DEPENDENT,
                                  DEPENDENT]),
                pattern='none', rate_hz=None))
        summary_nodes.append((layer, Node(
            id=f'p/n{index}', package='p', executable=f'n{index}',
            kind='executable', publishers=publishers)))
    for layer, node in summary_nodes:
        if layer == 0:
            continue  # sensors subscribe to nothing
        sources = topics_by_layer[layer - 1]
        if layer == 1:
            # feedback: odometry of the drivers reaches perception
            sources = sources + topics_by_layer[layers - 1][:20]
        node.subscribers = [NodeSubscriber(
            topic=rng.choice(sources), topic_is_literal=True, msg_type='m',
            api='a', callback='cb', namespace='', location='f:2')
            for _ in range(rng.randint(1, 3))]
    return build_graph([PackageSummary(
        package='p', path='/p', tool_version='0',
        nodes=[node for _, node in summary_nodes])])


def measure_memory(src, build_base):
    """Peak RSS (MB) of a fresh process analysing the workspace.

    The process's own peak plus that of its largest worker process (the
    units are parsed in workers; those of the fork server reach our
    children's figure once it has ended).
    """
    code = (
        'import multiprocessing.forkserver, resource, sys\n'
        'from colcon_rsia.package import workers\n'
        'from colcon_rsia.package.analysis import analyze_package\n'
        'from pathlib import Path\n'
        f'src = Path({str(src)!r}); build = Path({str(build_base)!r})\n'
        'for package in sorted(src.iterdir()):\n'
        '    analyze_package(name=package.name, path=str(package),\n'
        '                    build_base=str(build / package.name),\n'
        '                    use_cache=False, header_mode="exact")\n'
        'workers.shutdown()\n'
        'multiprocessing.forkserver._forkserver._stop()\n'
        'print((resource.getrusage(resource.RUSAGE_SELF).ru_maxrss +\n'
        '       resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)\n'
        '      / 1024)\n')
    result = subprocess.run([sys.executable, '-c', code], check=True,
                            capture_output=True, text=True)
    return float(result.stdout.strip().splitlines()[-1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--packages', type=int, default=4)
    parser.add_argument('--nodes', type=int, default=2000,
                        help='nodes of the synthetic system graph')
    parser.add_argument('--root', default='/tmp/rsia-bench-run')
    args = parser.parse_args()
    root = Path(args.root)
    src = root / 'src'
    if src.exists():
        subprocess.run(['rm', '-rf', str(src)], check=True)
    generate_workspace(src, args.packages)
    print(f'workspace: {args.packages} packages, {3 * args.packages} nodes')

    plain, _ = colcon_build(src, root / 'plain')
    print(f'build without rsia: {plain:.1f}s')
    results = {}
    for mode in ('model', 'exact'):
        os.environ['COLCON_RSIA_HEADER_MODE'] = mode
        elapsed, out = colcon_build(src, root / mode, handler=True)
        results[mode] = elapsed
        print(f'build with rsia ({mode}): {elapsed:.1f}s, analysis '
              f'{analysis_seconds(out):.1f}s')
    # the first build also reads the headers from disk: the one without
    # rsia is built again last, and the faster of the two is the reference
    again, _ = colcon_build(src, root / 'plain_again')
    print(f'build without rsia, again: {again:.1f}s')
    plain = min(plain, again)
    os.environ['COLCON_RSIA_HEADER_MODE'] = 'model'
    started = time.monotonic()
    rebuild = subprocess.run(
        [colcon(), 'build', '--base-paths', str(src),
         '--event-handlers', 'rsia+', '--cmake-args'] + CMAKE_ARGS,
        cwd=str(root / 'model'), capture_output=True, text=True, check=True,
        env=dict(os.environ, COLCON_HOME=str(root / 'model' / '.home')))
    nochange = analysis_seconds(rebuild.stdout)
    nochange_wait = waited_seconds(rebuild.stdout)
    print(f'no-change rebuild: {time.monotonic() - started:.1f}s, analysis '
          f'{nochange:.2f}s beside the build, which then waited '
          f'{nochange_wait:.2f}s for it')

    system = synthetic_system(args.nodes)
    ids = sorted(system.instances)
    rng = random.Random(2)
    samples = [rng.choice(ids) for _ in range(50)]
    started = time.monotonic()
    for node_id in samples:
        rate_impact(system, [node_id])
        traditional_impact(system, [node_id])
    impact_ms = (time.monotonic() - started) / len(samples) * 1000
    started = time.monotonic()
    table = impact_all(system)
    all_s = time.monotonic() - started
    print(f'{args.nodes}-node graph: impact {impact_ms:.1f} ms, --all '
          f'{all_s:.2f}s over {len(table["nodes"])} nodes, ratio '
          f'{table["ratio"]}')
    peak_mb = measure_memory(src, root / 'exact' / 'build')
    print(f'analysis peak memory: {peak_mb:.0f} MB')
    print(json.dumps({'build_s': plain, **results}))
    print(f'RESULT overhead_model={(results["model"] - plain) / plain:.2f} '
          f'overhead_exact={(results["exact"] - plain) / plain:.2f} '
          f'nochange_analysis_s={nochange:.2f} '
          f'nochange_wait_s={nochange_wait:.2f} impact_ms={impact_ms:.1f} '
          f'all_s={all_s:.2f} peak_mb={peak_mb:.0f}')


if __name__ == '__main__':
    main()
