# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The model header mode gives the facts of the real ROS headers, without ROS.

Every translation unit of test_workspaces/ros1 (compiled once by the session
fixture) is parsed twice: as colcon_rsia.package.analysis does, with the real headers
and the compile database's arguments, and in the model mode
(colcon_rsia.frontend.cpp.model_mode), and the facts of both must be equal.
"""

import glob
import os
from pathlib import Path
import time

from colcon_rsia.frontend import cpp
from colcon_rsia.frontend.compile_db import load_compile_database
from colcon_rsia.frontend.cpp import model_mode
from model_sources import parse_unit
import pytest


REPO = Path(__file__).resolve().parents[2]
ROS1_SRC = REPO / 'test_workspaces' / 'ros1' / 'src'
ROS1_PACKAGES = sorted(
    p.name for p in ROS1_SRC.iterdir() if (p / 'package.xml').is_file())

# where a machine with ROS 1 keeps the headers the model mode replaces
REAL_ROS_HEADER_DIRS = tuple(
    os.path.join('/usr/include', d) + '/' for d in (
        'ros', 'roscpp', 'rosconsole', 'console_bridge', 'xmlrpcpp', 'tf',
        'tf2', 'tf2_ros', 'tf2_msgs', 'tf2_geometry_msgs', 'image_transport',
        'message_filters', 'actionlib', 'actionlib_msgs', 'nodelet',
        'pluginlib', 'class_loader', 'diagnostic_updater', 'diagnostic_msgs',
        'dynamic_reconfigure', 'realtime_tools', 'std_msgs', 'std_srvs',
        'sensor_msgs', 'geometry_msgs', 'nav_msgs', 'rosgraph_msgs', 'boost',
    )) + ('/opt/ros/',)


def _facts(tu, *, package_path, file):
    """The facts of a TU as a dict, without the parse diagnostics.

    Nothing else is normalised: USRs of locals embed the offset of the
    declaration in the user's own file, which both modes share.
    """
    facts = cpp.extract_facts(
        tu, package_path=str(package_path),
        source=os.path.relpath(str(file), str(package_path))).to_dict()
    facts.pop('diagnostics', None)
    return facts


def _differences(exact, model):
    lines = []
    for key in exact:
        if exact[key] == model.get(key):
            continue
        lines.append(f'{key}:')
        if isinstance(exact[key], list):
            lines += [f'  only exact: {item}' for item in exact[key]
                      if item not in model[key]]
            lines += [f'  only model: {item}' for item in model[key]
                      if item not in exact[key]]
            lines.append('  (and maybe another order or number of items)')
        else:
            lines.append(f'  {exact[key]!r} != {model.get(key)!r}')
    return '\n'.join(lines)


def _entries(workspace, package):
    path = workspace.build_base / package / 'compile_commands.json'
    if not path.is_file():
        return []
    src = str(workspace.src / package) + '/'
    return [e for e in load_compile_database(str(path))
            if e.file.startswith(src)]


def _model_arguments(workspace, package, entry, stub_dir):
    return model_mode.prepare_model_arguments(
        source=entry.file, arguments=entry.arguments,
        package_path=str(workspace.src / package),
        workspace_package_dirs=sorted(
            str(p) for p in workspace.src.iterdir() if p.is_dir()),
        stub_dir=str(stub_dir),
        directory=entry.directory)


def _real_ros_includes(tu):
    found = set()
    for inclusion in tu.get_includes():
        if inclusion.include is None:
            continue
        name = os.path.realpath(inclusion.include.name)
        if name.startswith(REAL_ROS_HEADER_DIRS):
            found.add(name)
    return sorted(found)


@pytest.mark.parametrize('package', ROS1_PACKAGES)
def test_model_facts_equal_exact_facts(ros1_workspace, package, tmp_path):
    entries = _entries(ros1_workspace, package)
    if not entries:
        pytest.skip(f'{package} compiles no translation unit (header-only)')
    timings = []
    # the units with ROS facts: a main() that only runs a class another
    # unit defines (ekf_node's FilterNode<Ekf>) has none of its own
    proving = []
    for entry in entries:
        started = time.monotonic()
        exact_tu = parse_unit(file=entry.file, arguments=entry.arguments,
                              directory=entry.directory)
        exact_seconds = time.monotonic() - started
        exact = _facts(exact_tu, package_path=ros1_workspace.src / package,
                       file=entry.file)
        assert cpp.parse_diagnostics(exact_tu) == [], entry.file

        arguments = _model_arguments(
            ros1_workspace, package, entry, tmp_path / 'stubs')
        started = time.monotonic()
        model_tu = parse_unit(file=entry.file, arguments=arguments,
                              directory=entry.directory)
        model_seconds = time.monotonic() - started
        model = _facts(model_tu, package_path=ros1_workspace.src / package,
                       file=entry.file)

        assert model == exact, \
            f'{entry.file}: the model mode gives other facts\n' + \
            _differences(exact, model)
        if any(exact[key] for key in (
                'publishers', 'subscribers', 'publish_sites', 'timers')):
            proving.append(entry.file)
        timings.append((os.path.basename(entry.file), exact_seconds,
                        model_seconds))
    assert proving, f'{package}: units without ROS facts prove nothing'
    for name, exact_seconds, model_seconds in timings:
        print(f'{package}/{name}: exact {exact_seconds:.2f} s, '
              f'model {model_seconds:.2f} s')
    # the point of the mode (it is ~5x faster; 1x leaves room for a busy CI)
    assert sum(t[2] for t in timings) < sum(t[1] for t in timings)


@pytest.mark.parametrize('package', ROS1_PACKAGES)
def test_model_mode_reads_no_real_ros_header(ros1_workspace, package,
                                             tmp_path):
    entries = _entries(ros1_workspace, package)
    if not entries:
        pytest.skip(f'{package} compiles no translation unit (header-only)')
    stub_dir = tmp_path / 'stubs'
    for entry in entries:
        arguments = _model_arguments(ros1_workspace, package, entry, stub_dir)
        # include directories: the model, the sources, the stand-ins
        directories = [arguments[i + 1] for i, a in enumerate(arguments)
                       if a in ('-I', '-isystem', '-iquote')]
        allowed = (model_mode.MODEL_HEADERS_DIR, str(ros1_workspace.src),
                   str(stub_dir))
        assert all(d.startswith(allowed) for d in directories), arguments
        tu = parse_unit(file=entry.file, arguments=arguments,
                        directory=entry.directory)
        assert _real_ros_includes(tu) == [], entry.file
        assert cpp.parse_diagnostics(tu) == [], entry.file
    # stand-ins are written into the stub directory only
    assert (stub_dir / 'rsia_model' / 'fields.h').is_file()
    assert not glob.glob(str(ros1_workspace.src / '**' / 'rsia_model'),
                         recursive=True)


# More API forms than the test workspace uses, compiled against the real
# headers of this machine: subscribe with const members, shared pointers,
# MessageEvent, lambdas and boost::function; createTimer with a bare rate;
# the three service forms; every console macro family; BOOST_FOREACH; action
# servers and clients; message filters; image_transport; realtime_tools
# behind boost::make_shared; nodelets with NODELET_* and PLUGINLIB_EXPORT_CLASS.
MORE_FORMS = {
    'xpkg': {
        'include/xpkg/helper.h': """\
#pragma once
#include <string>
#include <ros/ros.h>
#include <std_msgs/String.h>

namespace xpkg
{
inline std::string describe(const std_msgs::String& s) { return "msg " + s.data; }
double computeGain(double x);
}
""",
        'src/extra.cpp': """\
#include <boost/foreach.hpp>
#include <boost/make_shared.hpp>
#include <boost/bind.hpp>
#include <ros/ros.h>
#include <roscpp/Empty.h>
#include <roscpp/GetLoggers.h>
#include <std_msgs/String.h>
#include <std_msgs/Float64.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/LaserScan.h>
#include <geometry_msgs/PoseStamped.h>
#include <diagnostic_msgs/DiagnosticStatus.h>
#include <actionlib/TestAction.h>
#include <actionlib/server/simple_action_server.h>
#include <actionlib/server/action_server.h>
#include <actionlib/client/simple_action_client.h>
#include <actionlib/client/action_client.h>
#include <message_filters/subscriber.h>
#include <message_filters/sync_policies/exact_time.h>
#include <message_filters/synchronizer.h>
#include <image_transport/image_transport.h>
#include <tf2_ros/transform_listener.h>
#include <tf/transform_datatypes.h>
#include <realtime_tools/realtime_publisher.h>
#include "xpkg/helper.h"

namespace xpkg
{

typedef actionlib::SimpleActionServer<actionlib::TestAction> Server;

double computeGain(double x) { return 2.0 * x; }

void freeImu(const sensor_msgs::Imu::ConstPtr& imu) { ROS_DEBUG("imu %f",
    imu->orientation.w); }
void freeEvent(const ros::MessageEvent<std_msgs::String const>& ev)
{
  ROS_INFO_STREAM("from " << ev.getPublisherName());
}
void freeTimer(const ros::TimerEvent&) {}
bool freeService(roscpp::Empty::Request&, roscpp::Empty::Response&) { return true; }
bool eventService(ros::ServiceEvent<roscpp::GetLoggers::Request,
    roscpp::GetLoggers::Response>& ev) { return true; }
void onConnect(const ros::SingleSubscriberPublisher& pub) { ROS_INFO("connected %s",
    pub.getSubscriberName().c_str()); }
void filterCb(const sensor_msgs::LaserScanConstPtr& scan) {}
void cameraCb(const sensor_msgs::ImageConstPtr& image,
    const sensor_msgs::CameraInfoConstPtr& info) {}

class Node
{
public:
  explicit Node(ros::NodeHandle& nh) : nh_(nh), pnh_("~"), child_(nh, "child"),
    as_(nh, "act", false), server_(nh, "srv_act", boost::bind(&Node::onGoal, this, _1),
        false),
    client_("client_act"), aclient_(nh, "raw_act"),
    scan_sub_(nh, "scan_mf", 3), imu_sub_(nh, "imu_mf", 3),
    sync_(Policy(10), scan_sub_, imu_sub_), listener_(buffer_), it_(nh)
  {
    pub_ = nh_.advertise<std_msgs::String>("chatter", 10, &onConnect);
    pub2_ = child_.advertise<std_msgs::Float64>("gain", 1,
        boost::bind(&Node::onSubConnect, this, _1), ros::SubscriberStatusCallback(),
            ros::VoidConstPtr(), true);
    sub1_ = nh_.subscribe("const_member", 1, &Node::constCb2, this);
    sub2_ = nh_.subscribe<std_msgs::String>("shared_member", 1, &Node::stringCb,
        shared_from_this_);
    sub3_ = nh_.subscribe("event", 1, freeEvent);
    sub4_ = nh_.subscribe("imu", 5, freeImu, ros::TransportHints().tcpNoDelay());
    sub5_ = nh_.subscribe<sensor_msgs::Imu>("imu_bind", 5, boost::bind(&Node::imuCb, this,
        _1, 42));
    sub6_ = pnh_.subscribe<std_msgs::String, const std_msgs::String&>("by_value", 1,
        [this](const std_msgs::String& s) { last_ = describe(s); });
    auto lam = [this](const std_msgs::Float64ConstPtr& f) { ROS_WARN_ONCE("%f",
        f->data); };
    sub7_ = nh_.subscribe<std_msgs::Float64>("lambda_var", 1, lam);
    timer1_ = nh_.createTimer(10.0, &Node::onTimer, this);
    timer2_ = nh_.createTimer(ros::Duration(0.25), boost::bind(&Node::onTimer, this, _1),
        true);
    timer3_ = nh_.createTimer(ros::Duration(ros::Rate(4.0)), freeTimer);
    timer4_ = nh_.createSteadyTimer(ros::WallDuration(0.5), &Node::onSteady, this);
    timer5_ = nh_.createWallTimer(ros::WallDuration(1, 0),
        [this](const ros::WallTimerEvent& e) { publishAll(); });
    srv1_ = nh_.advertiseService("free_srv", freeService);
    srv2_ = nh_.advertiseService("member_srv", &Node::memberService, this);
    srv3_ = nh_.advertiseService("event_srv", eventService);
    client_srv_ = nh_.serviceClient<roscpp::Empty>("other");
    as_.registerGoalCallback(boost::bind(&Node::goalCb, this));
    as_.registerPreemptCallback([this]() { ROS_INFO("preempt"); });
    as_.start();
    sync_.registerCallback(boost::bind(&Node::syncCb, this, _1, _2));
    scan_sub_.registerCallback(filterCb);
    image_sub_ = it_.subscribe("img", 1, &Node::imageCb, this,
        image_transport::TransportHints("compressed"));
    cam_sub_ = it_.subscribeCamera("cam/image", 1, cameraCb);
    rt_ = boost::make_shared<realtime_tools::RealtimePublisher<std_msgs::String>>(nh_,
        "rt_topic", 2);
    rt2_.reset(new realtime_tools::RealtimePublisher<std_msgs::Float64>(nh_, "rt2", 1));
    double rate = 0;
    pnh_.param("rate", rate, 5.0);
    nh_.getParam("gain", gain_);
    ros::param::get("~flag", flag_);
    int queue = pnh_.param<int>("queue", 7);
    std::vector<std::string> names;
    pnh_.getParamCached("names", names);
    ROS_ASSERT_MSG(rate > 0, "rate %f from %s", rate,
        describe(std_msgs::String()).c_str());
  }

  void publishAll()
  {
    std::vector<std_msgs::String> msgs(3);
    BOOST_FOREACH(const std_msgs::String& m, msgs)
    {
      pub_.publish(m);
      ROS_INFO_THROTTLE(1.0, "%s", describe(m).c_str());
    }
    for (size_t i = 0; i < msgs.size(); ++i)
    {
      if (rt_->trylock())
      {
        rt_->msg_.data = msgs[i].data + "!";
        rt_->unlockAndPublish();
      }
    }
    std_msgs::Float64 g;
    g.data = computeGain(gain_);
    pub2_.publish(boost::make_shared<std_msgs::Float64>(g));
  }

  void loop()
  {
    ros::Rate r(ros::Duration(0.1));
    ros::WallRate wr(20);
    while (ros::ok())
    {
      switch (state_)
      {
        case diagnostic_msgs::DiagnosticStatus::OK:
          publishAll();
          break;
        case diagnostic_msgs::DiagnosticStatus::WARN:
          ROS_ERROR_STREAM_THROTTLE(2.0, "warn " << computeGain(1.0));
          break;
        default:
          break;
      }
      do
      {
        wr.sleep();
      } while (false);
      r.sleep();
    }
  }

private:
  typedef message_filters::sync_policies::ExactTime<sensor_msgs::LaserScan,
      sensor_msgs::Imu> Policy;
  void constCb(const std_msgs::String& s) const { ROS_INFO_COND(s.data.empty(),
      "empty"); }
  void stringCb(const std_msgs::String& s) {}
  void constCb2(const std_msgs::String::ConstPtr& s) const {}
  void imuCb(const sensor_msgs::ImuConstPtr& imu,
      int tag) { tf::Quaternion q; tf::quaternionMsgToTF(imu->orientation,
          q); yaw_ = tf::getYaw(q); }
  void onTimer(const ros::TimerEvent& e) { publishAll(); }
  void onSteady(const ros::SteadyTimerEvent& e) { ROS_DEBUG_NAMED("steady", "%f",
      (e.current_real - e.last_real).toSec()); }
  bool memberService(roscpp::Empty::Request& req,
      roscpp::Empty::Response& res) { publishAll(); return true; }
  void onGoal(const actionlib::TestGoalConstPtr& goal)
  {
    actionlib::TestResult r;
    r.result = goal->goal;
    server_.setSucceeded(r);
  }
  void goalCb() { auto g = as_.acceptNewGoal(); }
  void onSubConnect(const ros::SingleSubscriberPublisher& p) {}
  void syncCb(const sensor_msgs::LaserScanConstPtr& s,
      const sensor_msgs::ImuConstPtr& i) { publishAll(); }
  void imageCb(const sensor_msgs::ImageConstPtr& img) {}

  ros::NodeHandle nh_;
  ros::NodeHandle pnh_;
  ros::NodeHandle child_;
  Server as_;
  actionlib::SimpleActionServer<actionlib::TestAction> server_;
  actionlib::SimpleActionClient<actionlib::TestAction> client_;
  actionlib::ActionClient<actionlib::TestAction> aclient_;
  message_filters::Subscriber<sensor_msgs::LaserScan> scan_sub_;
  message_filters::Subscriber<sensor_msgs::Imu> imu_sub_;
  message_filters::Synchronizer<Policy> sync_;
  tf2_ros::Buffer buffer_;
  tf2_ros::TransformListener listener_;
  image_transport::ImageTransport it_;
  image_transport::Subscriber image_sub_;
  image_transport::CameraSubscriber cam_sub_;
  boost::shared_ptr<Node> shared_from_this_;
  boost::shared_ptr<realtime_tools::RealtimePublisher<std_msgs::String>> rt_;
  boost::shared_ptr<realtime_tools::RealtimePublisher<std_msgs::Float64>> rt2_;
  ros::Publisher pub_, pub2_;
  ros::Subscriber sub1_, sub2_, sub3_, sub4_, sub5_, sub6_, sub7_;
  ros::Timer timer1_, timer2_, timer3_;
  ros::SteadyTimer timer4_;
  ros::WallTimer timer5_;
  ros::ServiceServer srv1_, srv2_, srv3_;
  ros::ServiceClient client_srv_;
  std::string last_;
  double gain_ = 1.0;
  bool flag_ = false;
  double yaw_ = 0;
  int state_ = 0;
};

}  // namespace xpkg

int main(int argc, char** argv)
{
  ros::init(argc, argv, "extra");
  ros::NodeHandle nh;
  xpkg::Node node(nh);
  boost::shared_ptr<const sensor_msgs::LaserScan> first =
      ros::topic::waitForMessage<sensor_msgs::LaserScan>("scan", nh, ros::Duration(1.0));
  ros::AsyncSpinner spinner(2);
  spinner.start();
  node.loop();
  return 0;
}
""",
    },
    'npkg': {
        'src/nl.cpp': """\
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/CameraInfo.h>
#include <geometry_msgs/PointStamped.h>
#include <tf/transform_listener.h>
#include <tf/transform_broadcaster.h>
#include <tf2_ros/message_filter.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <message_filters/subscriber.h>
#include <image_transport/image_transport.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <diagnostic_updater/publisher.h>
#include <boost/make_shared.hpp>
#include <boost/thread/mutex.hpp>

namespace npkg
{

std::string label(int i) { return "n" + std::to_string(i); }

class Cloud : public nodelet::Nodelet
{
public:
  Cloud() : buffer_(), tf2_listener_(buffer_) {}

private:
  void onInit() override
  {
    ros::NodeHandle& nh = getMTNodeHandle();
    ros::NodeHandle& pnh = getMTPrivateNodeHandle();
    ros::NodeHandlePtr sub_nh = boost::make_shared<ros::NodeHandle>(nh, "sub");
    NODELET_INFO_STREAM("starting " << label(1));
    NODELET_WARN_THROTTLE(1.0, "%s", label(2).c_str());
    cloud_sub_.subscribe(pnh, "cloud", 5);
    filter_.reset(new tf2_ros::MessageFilter<sensor_msgs::PointCloud2>(cloud_sub_,
        buffer_, "map", 10, nh));
    filter_->registerCallback(boost::bind(&Cloud::onCloud, this,
        boost::placeholders::_1));
    out_ = sub_nh->advertise<sensor_msgs::PointCloud2>("out", 1);
    it_.reset(new image_transport::ImageTransport(nh));
    cam_pub_ = it_->advertiseCamera("cam/image_raw", 1, &Cloud::onImgConnect,
        &Cloud::onImgConnect);
    diag_.reset(new diagnostic_updater::Updater(nh, pnh));
    double minf = 1, maxf = 10;
    diag_pub_.reset(new diagnostic_updater::DiagnosedPublisher<geometry_msgs::PointStamped>(
        nh.advertise<geometry_msgs::PointStamped>("point", 1), *diag_,
        diagnostic_updater::FrequencyStatusParam(&minf, &maxf),
            diagnostic_updater::TimeStampStatusParam()));
    diag_->add("cloud", boost::bind(&Cloud::diagnose, this, boost::placeholders::_1));
    timer_ = nh.createTimer(ros::Duration(0.1), &Cloud::onTimer, this);
  }

  static void onImgConnect(const image_transport::SingleSubscriberPublisher& p) {}

  void onCloud(const sensor_msgs::PointCloud2ConstPtr& cloud)
  {
    boost::mutex::scoped_lock lock(mutex_);
    sensor_msgs::PointCloud2 out = *cloud;
    out.header.frame_id = "map";
    out_.publish(out);
    geometry_msgs::PointStamped p;
    p.header = cloud->header;
    diag_pub_->publish(p);
  }

  void onTimer(const ros::TimerEvent&)
  {
    tf::StampedTransform t;
    if (listener_.waitForTransform("map", "base", ros::Time(0), ros::Duration(0.1)))
    {
      listener_.lookupTransform("map", "base", ros::Time(0), t);
      tf::Transform inv = t.inverse();
      broadcaster_.sendTransform(tf::StampedTransform(inv, ros::Time::now(), "base",
          "map_inv"));
    }
    sensor_msgs::Image img;
    sensor_msgs::CameraInfo info;
    cam_pub_.publish(img, info, ros::Time::now());
    diag_->force_update();
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) { stat.add("frames",
      frames_); }

  tf2_ros::Buffer buffer_;
  tf2_ros::TransformListener tf2_listener_;
  tf::TransformListener listener_;
  tf::TransformBroadcaster broadcaster_;
  message_filters::Subscriber<sensor_msgs::PointCloud2> cloud_sub_;
  boost::shared_ptr<tf2_ros::MessageFilter<sensor_msgs::PointCloud2>> filter_;
  boost::shared_ptr<image_transport::ImageTransport> it_;
  image_transport::CameraPublisher cam_pub_;
  boost::shared_ptr<diagnostic_updater::Updater> diag_;
  typedef diagnostic_updater::DiagnosedPublisher<geometry_msgs::PointStamped> PointPublisher;
  boost::shared_ptr<PointPublisher> diag_pub_;
  ros::Publisher out_;
  ros::Timer timer_;
  boost::mutex mutex_;
  int frames_ = 0;
};

}  // namespace npkg

PLUGINLIB_EXPORT_CLASS(npkg::Cloud, nodelet::Nodelet)
""",
    },
}


@pytest.mark.parametrize('package', sorted(MORE_FORMS))
def test_model_facts_equal_exact_facts_for_more_api_forms(
        ros1_workspace, package, tmp_path):
    # the real headers' flags: those of the nodelet package (pluginlib too)
    entry, = _entries(ros1_workspace, 'rsia_nodelets')
    root = tmp_path / 'src' / package
    sources = []
    for relative, text in MORE_FORMS[package].items():
        (root / relative).parent.mkdir(parents=True, exist_ok=True)
        (root / relative).write_text(text)
        if relative.endswith('.cpp'):
            sources.append(root / relative)
    arguments = entry.arguments + [
        '-I' + str(root / 'include'),
        '-I' + str(ROS1_SRC / 'realtime_tools' / 'include')]
    for source in sources:
        exact_tu = parse_unit(file=source, arguments=arguments, directory=root)
        assert cpp.parse_diagnostics(exact_tu) == [], source
        exact = _facts(exact_tu, package_path=root, file=source)
        model_arguments = model_mode.prepare_model_arguments(
            source=str(source), arguments=arguments, package_path=str(root),
            workspace_package_dirs=[str(tmp_path / 'src'), str(ROS1_SRC)],
            stub_dir=str(tmp_path / 'stubs'), directory=str(root))
        model_tu = parse_unit(file=source, arguments=model_arguments,
                              directory=root)
        assert cpp.parse_diagnostics(model_tu) == [], source
        model = _facts(model_tu, package_path=root, file=source)
        assert model == exact, \
            f'{source}: the model mode gives other facts\n' + \
            _differences(exact, model)
        assert _real_ros_includes(model_tu) == []


ACME_SOURCE = """\
// acme_node: a vendor driver header and a message package that are not
// installed on the analysing machine.
#include <acme_driver/device.h>
#include <acme_msgs/Status.h>
#include <ros/ros.h>
#include <std_msgs/String.h>

class AcmeNode
{
public:
  explicit AcmeNode(ros::NodeHandle& nh) : device_("/dev/acme0")
  {
    status_pub_ = nh.advertise<acme_msgs::Status>("status", 5);
    command_sub_ = nh.subscribe("command", 1, &AcmeNode::onCommand, this);
    timer_ = nh.createTimer(ros::Duration(0.1), &AcmeNode::onTimer, this);
  }

private:
  void onCommand(const std_msgs::String::ConstPtr& msg)
  {
    device_.send(msg->data);
  }

  void onTimer(const ros::TimerEvent&)
  {
    acme_msgs::Status status;
    status.temperature = device_.temperature();
    status.ok = status.temperature < acme_msgs::Status::MAX_TEMPERATURE;
    status_pub_.publish(status);
  }

  acme_driver::Device device_;
  ros::Publisher status_pub_;
  ros::Subscriber command_sub_;
  ros::Timer timer_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "acme_node");
  ros::NodeHandle nh;
  AcmeNode node(nh);
  ros::Rate rate(2.0);
  while (ros::ok())
  {
    acme_driver::Device::poll();
    ros::spinOnce();
    rate.sleep();
  }
  return 0;
}
"""


def test_unknown_and_missing_headers_keep_the_facts(tmp_path):
    package = tmp_path / 'src' / 'acme_node'
    (package / 'src').mkdir(parents=True)
    source = package / 'src' / 'acme_node.cpp'
    source.write_text(ACME_SOURCE)
    stub_dir = tmp_path / 'stubs'
    arguments = model_mode.prepare_model_arguments(
        source=str(source),
        arguments=['-DROS_PACKAGE_NAME="acme_node"', '-std=gnu++17'],
        package_path=str(package), workspace_package_dirs=[str(tmp_path / 'src')],
        stub_dir=str(stub_dir))
    tu = parse_unit(file=source, arguments=arguments, directory=package)
    facts = cpp.extract_facts(tu, package_path=str(package),
                              source='src/acme_node.cpp')

    # both includes got a stand-in, outside the source tree
    assert (stub_dir / 'acme_driver' / 'device.h').is_file()
    assert 'struct Status_' in \
        (stub_dir / 'acme_msgs' / 'Status.h').read_text()
    assert sorted(p.name for p in package.rglob('*')) == [
        'acme_node.cpp', 'src']
    # what the source uses of the unknown driver is declared as catch-alls
    assert 'struct Device ' in \
        (stub_dir / 'rsia_model' / 'unknown' / 'acme_driver.h').read_text()
    assert cpp.parse_diagnostics(tu) == []

    functions = {f.id: f.name for f in facts.functions}
    publisher, = facts.publishers
    assert (publisher.topic, publisher.msg_type, publisher.handle_name) == \
        ('status', 'acme_msgs::Status', 'status_pub_')
    subscriber, = facts.subscribers
    assert (subscriber.topic, subscriber.msg_type,
            functions[subscriber.callback]) == \
        ('command', 'std_msgs::String', 'AcmeNode::onCommand')
    timer, = facts.timers
    assert (functions[timer.callback], timer.rate_hz) == \
        ('AcmeNode::onTimer', 10.0)
    site, = facts.publish_sites
    assert (functions[site.function], site.handle) == \
        ('AcmeNode::onTimer', publisher.handle)
    rate, = facts.rates
    assert rate.rate_hz == 2.0
    loop, = facts.paced_loops
    assert (functions[loop.function], loop.rate_handle) == \
        ('main', rate.handle)


def test_arguments_keep_source_trees_only(tmp_path):
    workspace = tmp_path / 'ws'
    package = workspace / 'src' / 'pkg'
    other = workspace / 'src' / 'other'
    build = workspace / 'src' / 'build_in_src'
    for directory in (package / 'include', package / 'src',
                      other / 'include', build / 'include', workspace /
                      'devel' / 'include'):
        directory.mkdir(parents=True)
    (build / 'COLCON_IGNORE').write_text('')
    source = package / 'src' / 'node.cpp'
    source.write_text('int main() { return 0; }\n')
    stub_dir = tmp_path / 'stubs'
    arguments = model_mode.prepare_model_arguments(
        source=str(source), arguments=[
            '-DNAME="x"', '-D', 'OTHER=1', '-UNDEBUG', '-std=gnu++17', '-O2',
            '-Wall', '-fPIC', '-I' + str(package / 'include'),
            '-isystem', str(other / 'include'), '-I', '/usr/include/xmlrpcpp',
            '-I' + str(build / 'include'),
            '-I' + str(workspace / 'devel' / 'include'), '-Irelative'],
        package_path=str(package), workspace_package_dirs=[str(workspace / 'src')],
        stub_dir=str(stub_dir), directory=str(package))
    assert arguments[:2] == ['-I', model_mode.MODEL_HEADERS_DIR]
    kept = arguments[2:arguments.index(str(stub_dir)) - 1]
    assert kept == [
        '-DNAME="x"', '-DOTHER=1', '-UNDEBUG', '-std=gnu++17',
        '-I', str(package / 'include'), '-isystem', str(other / 'include'),
        '-I', str(package / 'relative')]


def test_include_scan_survives_odd_sources(tmp_path):
    package = tmp_path / 'src' / 'pkg'
    include = package / 'include' / 'pkg'
    include.mkdir(parents=True)
    (package / 'src').mkdir()
    # a cycle, a quote include next to the includer, non-UTF-8 bytes
    (include / 'a.h').write_text('#pragma once\n#include "b.h"\n')
    (include / 'b.h').write_bytes(
        b'#pragma once\n#include <pkg/a.h>\n// caf\xe9 \xff\n'
        b'#include <vendor_sdk/api.hpp>\n')
    source = package / 'src' / 'node.cpp'
    source.write_bytes(
        b'#include <pkg/a.h>\n'
        b'#include "missing_local.h"\n'
        b'#include "../gone/up.h"\n'
        b'#include <vector>\n#include <sys/time.h>\n'
        b'#include <no_such_header_anywhere_rsia.h>\n'
        b'#include <roscpp/Empty.h>\n#include <pkg_msgs/ModeAction.h>\n'
        b'#include <pkg/ControllerConfig.h>\n#include <pkg/missing.h>\n'
        b'bool cb(roscpp::Empty::Request&, roscpp::Empty::Response&);\n'
        b'void reconfigure(pkg::ControllerConfig & config, uint32_t level);\n'
        b'static vendor_sdk::Client client(vendor_sdk::DEFAULT_PORT, 2);\n'
        b'int main() { return vendor_sdk::connect(client).code; } // \xe9\n')
    stub_dir = tmp_path / 'stubs'
    arguments = model_mode.prepare_model_arguments(
        source=str(source),
        arguments=['-std=gnu++17', '-I' + str(package / 'include')],
        package_path=str(package), workspace_package_dirs=[], stub_dir=str(stub_dir))

    def stub(name):
        return (stub_dir / name).read_text()

    assert 'kind=empty' in stub('vendor_sdk/api.hpp')
    assert 'kind=empty' in stub('missing_local.h')
    assert 'kind=empty' in stub('no_such_header_anywhere_rsia.h')
    assert not (stub_dir / 'vector').exists()
    assert not (stub_dir / 'sys').exists()
    # a service (its Request is used), an action, a dynamic_reconfigure config
    assert 'struct Empty\n' in stub('roscpp/Empty.h')
    assert 'struct EmptyRequest_' in stub('roscpp/EmptyRequest.h')
    assert '_action_goal_type' in stub('pkg_msgs/ModeAction.h')
    assert '_goal_type' in stub('pkg_msgs/ModeActionGoal.h')
    assert 'struct ModeGoal_' in stub('pkg_msgs/ModeGoal.h')
    assert 'class ControllerConfig ' in stub('pkg/ControllerConfig.h')
    # names used from an unknown library get catch-all declarations
    unknown = stub('rsia_model/unknown/vendor_sdk.h')
    assert 'struct Client ' in unknown
    assert 'extern ::rsia_model::Any connect;' in unknown
    assert 'constexpr int DEFAULT_PORT = 1;' in unknown
    # but what a stand-in declares (pkg's config) is the stand-in's: the
    # namespace's header includes it instead
    unknown = stub('rsia_model/unknown/pkg.h')
    assert '#include <pkg/ControllerConfig.h>' in unknown
    assert 'ControllerConfig :' not in unknown
    assert '-DRSIA_MODEL_OWN_pkg' not in arguments
    # `../gone/up.h` is found through an extra directory inside the stubs
    up = [arguments[i + 1] for i, a in enumerate(arguments[:-1])
          if a == '-I' and arguments[i + 1].startswith(str(stub_dir / '_up'))]
    assert len(up) == 1
    assert (Path(up[0]) / '..' / 'gone' / 'up.h').resolve().is_file()
    tu = parse_unit(file=source, arguments=arguments, directory=package)
    assert cpp.parse_diagnostics(tu) == []
