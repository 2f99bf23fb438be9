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

import clang.cindex as ci
from colcon_rsia.frontend import cpp
from colcon_rsia.frontend.compile_db import find_resource_dir
from colcon_rsia.frontend.compile_db import load_compile_database
from colcon_rsia.frontend.cpp import model_mode
from colcon_rsia.frontend.cpp.model_mode import source_names
from colcon_rsia.frontend.cpp.model_mode.recovery import store
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


def _parse(*, file, arguments, directory):
    return cpp.parse(
        ci.Index.create(), file=str(file), arguments=arguments,
        resource_dir=find_resource_dir(), working_directory=str(directory))


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
        exact_tu = _parse(file=entry.file, arguments=entry.arguments,
                          directory=entry.directory)
        exact_seconds = time.monotonic() - started
        exact = _facts(exact_tu, package_path=ros1_workspace.src / package,
                       file=entry.file)
        assert cpp.parse_diagnostics(exact_tu) == [], entry.file

        arguments = _model_arguments(
            ros1_workspace, package, entry, tmp_path / 'stubs')
        started = time.monotonic()
        model_tu = _parse(file=entry.file, arguments=arguments,
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
        tu = _parse(file=entry.file, arguments=arguments,
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
        exact_tu = _parse(file=source, arguments=arguments, directory=root)
        assert cpp.parse_diagnostics(exact_tu) == [], source
        exact = _facts(exact_tu, package_path=root, file=source)
        model_arguments = model_mode.prepare_model_arguments(
            source=str(source), arguments=arguments, package_path=str(root),
            workspace_package_dirs=[str(tmp_path / 'src'), str(ROS1_SRC)],
            stub_dir=str(tmp_path / 'stubs'), directory=str(root))
        model_tu = _parse(file=source, arguments=model_arguments,
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
    tu = _parse(file=source, arguments=arguments, directory=package)
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
    # names used from an unknown library get catch-all declarations, unless
    # the TU declares that namespace itself (here: it has pkg's config)
    unknown = stub('rsia_model/unknown/vendor_sdk.h')
    assert 'struct Client ' in unknown
    assert 'extern ::rsia_model::Any connect;' in unknown
    assert 'constexpr int DEFAULT_PORT = 1;' in unknown
    assert '-DRSIA_MODEL_OWN_pkg' in arguments
    # `../gone/up.h` is found through an extra directory inside the stubs
    up = [arguments[i + 1] for i, a in enumerate(arguments[:-1])
          if a == '-I' and arguments[i + 1].startswith(str(stub_dir / '_up'))]
    assert len(up) == 1
    assert (Path(up[0]) / '..' / 'gone' / 'up.h').resolve().is_file()
    tu = _parse(file=source, arguments=arguments, directory=package)
    assert cpp.parse_diagnostics(tu) == []


def _sources(tmp_path, **texts):
    """A package `pkg` with these files in src/: (package, [paths])."""
    package = tmp_path / 'src' / 'pkg'
    (package / 'src').mkdir(parents=True)
    paths = []
    for name, text in texts.items():
        paths.append(package / 'src' / f'{name}.cpp')
        paths[-1].write_text(text)
    return package, paths


def _prepare(package, source, stub_dir):
    return model_mode.prepare_model_arguments(
        source=str(source), arguments=['-std=gnu++17'],
        package_path=str(package), workspace_package_dirs=[],
        stub_dir=str(stub_dir))


def _assert_parses_clean(tmp_path, code, repairs=()):
    """A package of this one source parses in model mode without errors.

    :param repairs: what the unit's repair header declares, if anything
    """
    package, [source] = _sources(tmp_path, node=code)
    stub_dir = tmp_path / 'stubs'
    arguments = _prepare(package, source, stub_dir)
    if repairs:
        header = store.repair_header(str(stub_dir), str(source))
        store.add_repairs(header, str(source), set(repairs))
        arguments = ['-include', header] + arguments
    tu = _parse(file=source, arguments=arguments, directory=package)
    assert cpp.parse_diagnostics(tu) == []


def test_real_code_idioms_type_check_without_repairs(tmp_path):
    # what autoware-style code does with the ROS model and libraries the
    # model lacks; each line was a parse error before the model took it
    package, [source] = _sources(tmp_path, node=r"""
#include <algorithm>
#include <chrono>
#include <vector>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/header.hpp>
#include <std_srvs/srv/trigger.hpp>
#include <tf2/LinearMath/Quaternion.h>
#include <geo_utils/stop_watch.hpp>
#include <geo_utils/geometry.hpp>

using geo_utils::StopWatch;
using geo_utils::motion::calc_length;

double run(const std_msgs::msg::Header & header, rclcpp::Node & node,
           const geo_utils::Vector2d & a, const geo_utils::Vector2d & b)
{
  // a class template and a function template of an unknown library
  StopWatch<std::chrono::milliseconds> stop_watch;
  const bool enabled = geo_utils::get_or_declare<bool>(node, "enabled");
  // arithmetic and comparisons on its classes
  geo_utils::Vector2d d = a - b;
  const bool same = a == b;
  // a vector of its class filled from a catch-all value
  std::vector<geo_utils::Polygon> polygons;
  polygons.push_back(geo_utils::make_polygon(d));
  // a time from now minus a message's stamp, a field against a number
  const double age = (node.now() - header.stamp).seconds();
  const double capped = std::min(header.stamp.sec, 10);
  // a message's SharedPtr from a polling subscriber of that library
  std_msgs::msg::Header::ConstSharedPtr last;
  last = geo_utils::poller.take_data();
  // a pointer of that library, and a string made from a field
  geo_utils::PortHandler * port = geo_utils::PortHandler::getPortHandler(
    header.frame_id);
  const std::string frame(header.frame_id);
  // rclcpp and tf2 members real code uses
  const rclcpp::Duration timeout(header.stamp);
  node.get_logger().set_level(rclcpp::Logger::Level::Debug);
  rclcpp::Service<std_srvs::srv::Trigger>::CallbackType on_trigger;
  const tf2::Quaternion q(0, 0, 0, 1);
  const double w = q.getW() + timeout.seconds();
  // a function of a namespace inside it, also through a using-declaration
  const double length = calc_length(d) + geo_utils::motion::calc_length(d);
  return enabled && same && port && !frame.empty() && on_trigger ?
         age + length + w : capped;
}
""")
    stub_dir = tmp_path / 'stubs'
    arguments = _prepare(package, source, stub_dir)
    unknown = (stub_dir / 'rsia_model' / 'unknown' / 'geo_utils.h').read_text()
    assert 'template <class...> struct StopWatch' in unknown
    assert 'get_or_declare(RsiaA&&...);' in unknown
    assert 'namespace motion\n' in unknown
    tu = _parse(file=source, arguments=arguments, directory=package)
    assert cpp.parse_diagnostics(tu) == []


def test_a_catch_all_pointers_element_type_is_a_catch_all(tmp_path):
    # `decltype(sub_)::element_type::create_subscription(...)`: the static
    # call through what a catch-all `SharedPtr` points to
    _assert_parses_clean(tmp_path, r"""
#include <rclcpp/rclcpp.hpp>
#include <geo_utils/polling.hpp>
#include <std_msgs/msg/header.hpp>
struct Selector : rclcpp::Node
{
  Selector() : Node("selector")
  {
    sub_ = decltype(sub_)::element_type::create_subscription(this, "in", 1);
    auto other = this->create_subscription<std_msgs::msg::Header>(
      "other", 1, [](std_msgs::msg::Header::ConstSharedPtr) {});
  }
  geo_utils::Poller<std_msgs::msg::Header>::SharedPtr sub_;
};
""")


def test_an_unknown_function_takes_types_and_values_as_template_arguments(
        tmp_path):
    # boost.geometry's `get<min_corner, 0>(box)` inside a constructor's
    # arguments, `get<0>(point)`, and range-v3's `to<std::vector>()`
    _assert_parses_clean(tmp_path, r"""
#include <vector>
#include <boost/geometry.hpp>
#include <range/v3/range/conversion.hpp>
namespace bg = boost::geometry;
struct Point { Point(double x, double y); };
struct Box { Box(const Point & a, const Point & b); };
double area(const bg::model::box<bg::model::point_xy<double>> & hull)
{
  const Box box(
    Point(bg::get<bg::min_corner, 0>(hull), bg::get<bg::min_corner, 1>(hull)),
    Point(bg::get<bg::max_corner, 0>(hull), bg::get<1>(hull)));
  std::vector<double> xs = ranges::to<std::vector>();
  return xs.front();
}
""", repairs=[('namespace', 'boost::geometry'), ('namespace', 'ranges'),
              ('function', 'ranges::to'),
              ('namespace', 'boost::geometry::model'),
              ('template', 'boost::geometry::model::box'),
              ('template', 'boost::geometry::model::point_xy'),
              ('constant', 'boost::geometry::min_corner'),
              ('constant', 'boost::geometry::max_corner'),
              ('function', 'boost::geometry::get')])


def test_rosidls_message_trait_holds_for_messages(tmp_path):
    # a ROS 2 library's publisher helper that takes messages only
    _assert_parses_clean(tmp_path, r"""
#include <map>
#include <string>
#include <type_traits>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>
#include <acme_msgs/msg/float64_stamped.hpp>
class DebugPublisher
{
public:
  template <class T, std::enable_if_t<
    rosidl_generator_traits::is_message<T>::value, std::nullptr_t> = nullptr>
  void publish(const std::string & name, const T & data) {}
  template <class T, std::enable_if_t<
    !rosidl_generator_traits::is_message<T>::value, std::nullptr_t> = nullptr>
  void publish(const std::string & name, const T & value) {}
};
void report(DebugPublisher & debug, double seconds)
{
  acme_msgs::msg::Float64Stamped stamped;
  debug.publish<acme_msgs::msg::Float64Stamped>("time", stamped);
  debug.publish("value", std_msgs::msg::Float64());
  debug.publish("seconds", seconds);
  const std::string type = rosidl_generator_traits::name<acme_msgs::msg::Float64Stamped>();
  const std::string yaml = rosidl_generator_traits::to_yaml(stamped);
}
""")


def test_the_pointers_of_two_unknown_classes_are_two_types(tmp_path):
    # overloads on the pointers of two specialisations of an unknown class
    # template (PCL's point clouds), and what code does with such pointers
    _assert_parses_clean(tmp_path, r"""
#include <memory>
#include <vector>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
struct Debugger
{
  void add(const pcl::PointCloud<pcl::PointXY>::Ptr & input)
  {
    pcl::PointCloud<pcl::PointXYZ>::Ptr xyz(new pcl::PointCloud<pcl::PointXYZ>);
    xyz->points.reserve(input->points.size());
    add(xyz);
  }
  void add(const pcl::PointCloud<pcl::PointXYZ>::Ptr & input)
  {
    pcl::PointCloud<pcl::PointXYZ>::ConstPtr read_only = input;
    clouds_.push_back(pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>());
    clouds_.push_back(input);
    if (!input || input->empty() || read_only == nullptr) {
      return;
    }
  }
  std::vector<pcl::PointCloud<pcl::PointXYZ>::Ptr> clouds_;
};
""")


def test_an_unknown_librarys_lower_case_name_in_a_product_is_a_value(
        tmp_path):
    # `2 * geo_utils::pi * ratio` is no declaration of a pointer; a
    # declaration of one keeps its type
    _assert_parses_clean(tmp_path, r"""
#include <geo_utils/constants.hpp>
double angle(double ratio, geo_utils::handle_t * handle)
{
  geo_utils::handle_t * other = handle;
  const double theta = 2 * geo_utils::pi * ratio;
  return other ? theta : -geo_utils::pi * ratio;
}
""")


def test_a_member_one_unit_calls_with_template_arguments_is_a_template(
        tmp_path):
    package, [first, second] = _sources(
        tmp_path,
        first='#include <cv_like/mat.hpp>\n'
              'int first(cv_like::Mat & mat) { return mat.at(0); }\n',
        second='#include <cv_like/mat.hpp>\n'
               'void second(cv_like::Mat & mat) { mat.at<unsigned char>(1, 2) = 3; }\n')
    stub_dir = tmp_path / 'stubs'
    _prepare(package, first, stub_dir)
    # the first unit wrote `at` as a plain member; the second's use makes
    # it a member template, which takes the first's plain call too
    arguments = _prepare(package, second, stub_dir)
    fields = (stub_dir / 'rsia_model' / 'fields.h').read_text()
    assert 'RSIA_MODEL_FIELD_TEMPLATE(at)' in fields
    for source in (first, second):
        tu = _parse(file=source, arguments=arguments, directory=package)
        assert cpp.parse_diagnostics(tu) == []


def test_a_repair_of_another_kind_hides_the_unknown_librarys_declaration(
        tmp_path):
    # the unknown-library header takes `geo_utils::to_msg` for an object
    # (no call on the line); the unit's repair header, force-included
    # first, declared it as a function: the header must step aside
    package, [source] = _sources(
        tmp_path, node='#include <geo_utils/convert.hpp>\n'
                       'auto convert = geo_utils::to_msg;\n'
                       'void f() { geo_utils::to_msg(1, 2); }\n')
    stub_dir = tmp_path / 'stubs'
    arguments = _prepare(package, source, stub_dir)
    unknown = (stub_dir / 'rsia_model' / 'unknown' / 'geo_utils.h').read_text()
    assert 'extern ::rsia_model::Any to_msg;' in unknown
    header = store.repair_header(str(stub_dir), str(source))
    store.add_repairs(header, str(source), {('function', 'geo_utils::to_msg')})
    tu = _parse(file=source, arguments=arguments + ['-include', header],
                directory=package)
    assert [d for d in cpp.parse_diagnostics(tu) if 'redefinition' in d] == []


def test_a_lower_case_header_is_a_message_only_if_used_as_one():
    from colcon_rsia.frontend.cpp.model_mode.stand_ins import stand_ins_for
    # tf/tfMessage.h declares tf::tfMessage; fmt/format.h, a function
    [message] = stand_ins_for('tf/tfMessage.h', ['tf::tfMessage msg;']).values()
    assert 'kind=message' in message
    [library] = stand_ins_for(
        'fmt/format.h', ['auto text = fmt::format("{}", 1);']).values()
    assert 'kind=empty' in library
    # thrust/device_vector.h: a class template (a message takes no
    # template arguments)
    [library] = stand_ins_for(
        'thrust/device_vector.h',
        ['thrust::device_vector<float> points_;']).values()
    assert 'kind=empty' in library


@pytest.mark.parametrize('ros2', [True, False])
def test_point_cloud2_iterators_are_modelled(tmp_path, ros2):
    cloud = 'sensor_msgs::msg::PointCloud2' if ros2 else \
        'sensor_msgs::PointCloud2'
    header = 'sensor_msgs/point_cloud2_iterator.hpp' if ros2 else \
        'sensor_msgs/point_cloud2_iterator.h'
    package, [source] = _sources(tmp_path, node=f"""
#include <{header}>
float sum(const {cloud} & cloud, {cloud} & out)
{{
  float total = 0;
  for (sensor_msgs::PointCloud2ConstIterator<float> iter_x(cloud, "x"),
       iter_y(cloud, "y");
       iter_x != iter_x.end(); ++iter_x, ++iter_y) {{
    total += *iter_x + *iter_y;
  }}
  sensor_msgs::PointCloud2Modifier modifier(out);
  modifier.setPointCloud2FieldsByString(1, "xyz");
  sensor_msgs::PointCloud2Iterator<float> out_x(out, "x");
  *out_x = total;
  return total;
}}
""")
    stub_dir = tmp_path / 'stubs'
    arguments = _prepare(package, source, stub_dir)
    tu = _parse(file=source, arguments=arguments, directory=package)
    assert cpp.parse_diagnostics(tu) == []


def test_a_ros2_interface_keeps_every_spelling_its_units_use(tmp_path):
    # rosidl names `uuid.hpp` after `UUID`: the first unit spells it, the
    # second includes the header without naming the type (the stand-in
    # then guesses `Uuid`); prepared in parallel, the second unit's
    # stand-in must not take the first's name away
    package, [first, second] = _sources(
        tmp_path,
        first='#include <unique_identifier_msgs/msg/uuid.hpp>\n'
              'unique_identifier_msgs::msg::UUID id;\n'
              'unique_identifier_msgs::msg::UUID::SharedPtr ptr;\n',
        second='#include <unique_identifier_msgs/msg/uuid.hpp>\n'
               'int second() { return 0; }\n')
    stub_dir = tmp_path / 'stubs'
    arguments = _prepare(package, first, stub_dir)
    _prepare(package, second, stub_dir)
    tu = _parse(file=first, arguments=arguments, directory=package)
    assert cpp.parse_diagnostics(tu) == []
    stand_in = stub_dir / 'unique_identifier_msgs' / 'msg' / 'uuid.hpp'
    assert '// declares: UUID Uuid\n' in stand_in.read_text()


def test_node_graph_queries_parameter_listing_and_time_steps(tmp_path):
    package, [source] = _sources(tmp_path, node=r"""
#include <optional>
#include <builtin_interfaces/msg/time.hpp>
#include <rclcpp/rclcpp.hpp>

// a duration times a count (the real Duration converts to its message
// only), and a time into its message
builtin_interfaces::msg::Time later(rclcpp::Node & node, std::size_t steps)
{
  const rclcpp::Duration step(0, 100000000);
  return node.now() + step * steps;
}

// a time minus a std::chrono duration (which converts to a Duration only,
// not to a Time)
rclcpp::Time earlier(rclcpp::Node & node, int64_t count)
{
  return node.now() - std::chrono::nanoseconds(count);
}

// a time beside an optional one (which a Time does not convert from)
std::optional<rclcpp::Time> kept(
  rclcpp::Node & node, const std::optional<rclcpp::Time> & stamp)
{
  return !stamp.has_value() ? node.now() : stamp;
}

std::string first_publisher(rclcpp::Node & node)
{
  const auto names = node.list_parameters({"limits"}, 10).names;
  for (const auto & info : node.get_publishers_info_by_topic("/scan")) {
    return info.node_name() + info.node_namespace() + info.topic_type();
  }
  return node.get_subscriptions_info_by_topic("/scan").empty() ? "" : "x";
}
""")
    arguments = _prepare(package, source, tmp_path / 'stubs')
    tu = _parse(file=source, arguments=arguments, directory=package)
    assert cpp.parse_diagnostics(tu) == []


def test_constants_in_the_k_style_are_declared_for_nested_unknown_types():
    # TensorRT's `Severity::kINFO`, where Severity is a nested type of an
    # unknown class (rsia_model::Unknown): its constants are the Fields'
    constants = source_names.used_names(
        ['if (severity <= Severity::kINFO || s == Logger::CONNECTED) {}'])[1]
    assert {'kINFO', 'CONNECTED'} <= constants


def test_repaired_classes_hash_and_unknown_values_take_a_comma_initializer(
        tmp_path):
    _assert_parses_clean(tmp_path, r"""
#include <unordered_map>
#include <boost/uuid/uuid.hpp>
#include <eigen_like/core.hpp>

// a repaired class as the key of an unordered_map (its default
// constructor is deleted without a std::hash of the key)
std::unordered_map<boost::uuids::uuid, double> ages;

double run(const boost::uuids::uuid & id)
{
  ages[id] = 1.0;
  // Eigen's comma initializer on a class of the unknown library
  const eigen_like::Matrix3d m =
    (eigen_like::Matrix3d() << 1, 0, 0, 0, 1, 0, 0, 0, 1).finished();
  return ages.count(id) + m(0, 0);
}
""", {('type', 'boost::uuids::uuid')})


def test_sizes_and_c_strings_of_unknown_values_have_their_usual_types(
        tmp_path):
    package, [first, second] = _sources(tmp_path, first=r"""
#include <vector>
#include <std_msgs/msg/string.hpp>
#include <sensor_msgs/msg/point_cloud2.hpp>
#include <eigen_like/core.hpp>

std::size_t run(const std_msgs::msg::String & text,
                const sensor_msgs::msg::PointCloud2 & cloud,
                const eigen_like::MatrixXd & matrix)
{
  // a catch-all size() would tie between vector's size and copy
  // constructors; a catch-all c_str() would not become a const char *
  std::vector<double> widths(cloud.fields.size());
  std::vector<std::vector<double>> scores(matrix.rows(), std::vector<double>(matrix.cols()));
  const char * name = text.data.c_str();
  return widths.size() + scores.size() + (name != nullptr);
}
""", second=r"""
#include <std_msgs/msg/string.hpp>

// another unit takes `size` for a value: a member for every unit
double run(std_msgs::msg::String & text) { text.size = 3; return text.size * 2; }
""")
    stub_dir = tmp_path / 'stubs'
    arguments = _prepare(package, first, stub_dir)
    assert 'RSIA_MODEL_METHOD(size, std::size_t)' in (
        stub_dir / 'rsia_model' / 'fields.h').read_text()
    tu = _parse(file=first, arguments=arguments, directory=package)
    assert cpp.parse_diagnostics(tu) == []
    arguments = _prepare(package, second, stub_dir)
    fields = (stub_dir / 'rsia_model' / 'fields.h').read_text()
    assert 'RSIA_MODEL_FIELD(size)' in fields
    assert 'RSIA_MODEL_METHOD(c_str, const char *)' in fields
    tu = _parse(file=second, arguments=arguments, directory=package)
    assert cpp.parse_diagnostics(tu) == []


def test_classes_of_unknown_libraries_take_braces_and_iterated_elements(
        tmp_path):
    _assert_parses_clean(tmp_path, r"""
#include <vector>
#include <boost/optional.hpp>
#include <nav_msgs/msg/path.hpp>
#include <lanelet_like/lanelet.hpp>

void run(const nav_msgs::msg::Path & path, std::vector<lanelet_like::ConstLanelet> & lanelets)
{
  boost::optional<double> last;
  // `= {}` tied between the class's own assignments and those of its base
  last = {};
  last = path.poses.front();
  lanelet_like::Point2d point;
  point = {path.poses.front().pose.position.x, 2.0};
  // an element of a field binds to a reference of the class, and makes one
  // through the class's constructor: push_back(const T &) and
  // push_back(T &&) tied
  for (const auto & lanelet : path.poses) {
    lanelets.push_back(lanelet);
    const lanelet_like::ConstLanelet copy(lanelet);
  }
}
""", {('template', 'boost::optional')})


def test_catch_all_calls_take_braced_arguments(tmp_path):
    _assert_parses_clean(tmp_path, r"""
#include <vector>
#include <geometry_msgs/msg/point.hpp>
#include <grid_like/polygon.hpp>
#include <cv_like/imgproc.hpp>

void run(const geometry_msgs::msg::Point & p, grid_like::Polygon & polygon, cv_like::Mat & image)
{
  // a braced list deduces no template parameter of the catch-all calls
  polygon.addVertex({p.x, p.y});
  polygon.vertices.push_back({p.x, p.y, p.z});
  cv_like::copyMakeBorder(image, image, 0, 1, 0, 1, cv_like::BORDER_CONSTANT, {0, 0, 0});
  const auto resized = cv_like::resize<float>(image, {});
  const std::vector<double> values = grid_like::spline({1.0}, std::vector<double>{2.0}, {p.x});
  // lists of lists: a ring of points
  polygon.outer() = {{p.x, p.y}, {p.y, p.x}, {p.x, p.y}};
  polygon.outer() = {};
  const auto ring = grid_like::Polygon{{{p.x, p.y}, {p.y, p.x}}};
}
""")


def test_a_lambda_compares_catch_alls_with_a_constant_it_does_not_capture(
        tmp_path):
    _assert_parses_clean(tmp_path, r"""
#include <vector>
#include <grid_like/geometry.hpp>

void run(const std::vector<int> & points, std::vector<int> & bound)
{
  // a number compared with a catch-all is read, not referred to
  constexpr double overlap = 0.01;
  const auto add = [](const std::vector<int> & ps, std::vector<int> & b) {
    for (const auto & p : ps) {
      if (b.empty() || grid_like::distance(p, b.back()) > overlap) {
        b.push_back(p);
      }
    }
    return 2 * grid_like::distance(ps.front(), b.back()) + overlap;
  };
  add(points, bound);
}
""")


def test_a_panel_formats_what_its_node_receives_with_qstring(tmp_path):
    _assert_parses_clean(tmp_path, r"""
#include <string>
#include <QObject>

QString shown(const std::string & name, double seconds, int count)
{
  QString text = QString::fromStdString(name) + " ";
  text += QString::number(seconds, 'f', 3).rightRef(4);
  text += QString("%1 of %2").arg(count).arg(QString::number(count, 16));
  return text.isEmpty() ? QString::fromUtf8("-") : text.left(text.size() - 1);
}
""")


def test_rates_policies_iterators_and_pointer_casts_of_catch_all_values(
        tmp_path):
    _assert_parses_clean(tmp_path, r"""
#include <iterator>
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>
#include <map_like/primitives.hpp>

double run(rclcpp::Node & node, const std_msgs::msg::Float64 & rate,
           const map_like::Lanelet & lanelet)
{
  // a field is a rate in hertz, not a duration message
  const auto period = rclcpp::Rate(rate.data).period();
  rclcpp::WallRate wall(rate.data);
  const auto qos = rclcpp::QoS(1).durability(rclcpp::DurabilityPolicy::TransientLocal)
                     .reliability(rclcpp::ReliabilityPolicy::Reliable);
  const auto step = rclcpp::Duration::from_nanoseconds(
    static_cast<rcl_duration_value_t>(rate.data * 1e9));
  const auto vertices = lanelet.polygon();
  auto next = std::next(vertices.cbegin());
  const auto element = std::dynamic_pointer_cast<const map_like::Crosswalk>(
    lanelet.regulatoryElements().front());
  return period.count() + step.seconds() + (next != vertices.cend()) + (element != nullptr);
}
""")


def test_a_known_member_whose_result_has_members_stays_a_catch_all():
    # OpenCV's `image.size().width`: no number
    values = source_names.used_names(
        ['int w = image.size().width + path.c_str()[0]; n = v.rows();'])[5]
    assert 'size' in values
    assert not {'c_str', 'rows'} & values
    # also through a variable (`auto size = image.size();`); a count
    # used as a number is no such use
    values = source_names.used_names([
        'auto image_size = images[i].size(); decode(image_size);\n'
        'int w = image_size.width;\n'
        'auto n = path.c_str(); auto rows = m.rows(); f(n, rows + 1);'])[5]
    assert 'size' in values
    assert not {'c_str', 'rows'} & values


def test_a_trailing_return_type_is_no_member(tmp_path):
    # a member named `QBrush` in every catch-all would hide the class
    # (`-> QBrush {` of a lambda); a call's result stays a member access
    members, *_, templates, _ = source_names.used_names([
        'auto row = [&]() -> QBrush { return {}; };\n'
        'auto Box::pose() const -> std::vector<Pose> & { return p; }\n'
        'pub = node()->create_publisher<T>("a"); if (a()->ok) {}'])
    assert members == {'ok'} and templates == {'create_publisher'}
    _assert_parses_clean(tmp_path, r"""
#include <QBrush>
#include <QTableWidgetItem>
void paint(QTableWidgetItem * item, bool stale)
{
  const auto background = [&]() -> QBrush {
    if (stale) {
      return QBrush(Qt::red);
    }
    return {};
  }();
  item->setBackground(background);
}
""", repairs=[('type', 'QTableWidgetItem'), ('type', 'QBrush'),
              ('namespace', 'Qt'), ('object', 'Qt::red')])


def test_a_switch_takes_a_value_of_a_nested_unknown_type(tmp_path):
    # TensorRT's logger: `Severity` is a nested type of an unknown class
    _assert_parses_clean(tmp_path, r"""
#include <trt_like/logger.hpp>

int level(trt_like::ILogger::Severity severity)
{
  switch (severity) {
    case trt_like::ILogger::Severity::kERROR:
      return 2;
    case trt_like::ILogger::Severity::kINFO:
      return 1;
    default:
      return severity ? 0 : -1;
  }
}
""", {
        ('type', 'trt_like::ILogger'),
        ('member-type', 'trt_like::ILogger::Severity')})


def test_a_catch_all_value_becomes_a_pair(tmp_path):
    _assert_parses_clean(tmp_path, r"""
#include <utility>
#include <vector>
#include <opt_like/minima.hpp>

float run(const std::vector<double> & xs)
{
  // a pair from a function of an unknown library
  const std::pair<float, float> best = opt_like::minimize(xs, 0.0, 1.0);
  return best.first;
}
""")


def test_profiles_clock_waits_enum_results_and_constexpr_field_checks(
        tmp_path):
    # forms of ros2_control's controller manager
    _assert_parses_clean(tmp_path, r"""
#include <rclcpp/rclcpp.hpp>
#include <lifecycle_msgs/msg/state.hpp>
#include <handler_like/async_handler.hpp>

namespace pkg
{
enum class return_type : std::uint8_t { OK = 0, ERROR = 1 };

// every field of an rmw profile, as an aggregate
static const rmw_qos_profile_t qos_services = {
  RMW_QOS_POLICY_HISTORY_KEEP_ALL,
  1,
  RMW_QOS_POLICY_RELIABILITY_RELIABLE,
  RMW_QOS_POLICY_DURABILITY_VOLATILE,
  RMW_QOS_DEADLINE_DEFAULT,
  RMW_QOS_LIFESPAN_DEFAULT,
  RMW_QOS_POLICY_LIVELINESS_SYSTEM_DEFAULT,
  RMW_QOS_LIVELINESS_LEASE_DURATION_DEFAULT,
  false};

// a constexpr function comparing a message's field type
constexpr bool needs_no_action(const lifecycle_msgs::msg::State::_id_type state)
{
  return state == lifecycle_msgs::msg::State::PRIMARY_STATE_UNKNOWN ||
         state == lifecycle_msgs::msg::State::PRIMARY_STATE_FINALIZED;
}

return_type update(rclcpp::Node & node, handler_like::AsyncHandler & handler,
                   std::unique_ptr<rclcpp::PreShutdownCallbackHandle> & handle)
{
  node.get_node_base_interface()->get_context()->remove_pre_shutdown_callback(
    *(handle.get()));
  node.get_clock()->wait_until_started();
  const auto result = handler.trigger(node.now());
  return_type status = return_type::OK;
  // a catch-all value to a scoped enumeration
  status = result.second;
  return needs_no_action(result.first) && qos_services.depth ? status : return_type::ERROR;
}
}  // namespace pkg
""")


def test_noetic_time_constants_and_distances_from_a_field_iterator(tmp_path):
    # forms of ros_controllers' joint_state and joint_trajectory controllers
    _assert_parses_clean(tmp_path, r"""
#include <iterator>
#include <vector>
#include <ros/ros.h>
#include <trajectory_msgs/JointTrajectory.h>

double check(const trajectory_msgs::JointTrajectory & msg, std::vector<double> & v)
{
  typedef std::vector<trajectory_msgs::JointTrajectoryPoint>::const_iterator It;
  long n = 0;
  for (It it = msg.points.begin(); it != msg.points.end(); ++it) {
    n += std::distance(msg.points.begin(), it) + std::distance(it, msg.points.end());
  }
  n += std::distance(msg.points.begin(), msg.points.end()) + std::distance(v.begin(), v.end());
  const ros::Time last = ros::Time::MIN;
  return n + (last == ros::Time::ZERO) + ros::Duration::MAX.toSec();
}
""")


def test_a_switch_takes_a_message_field(tmp_path):
    _assert_parses_clean(tmp_path, r"""
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/u_int8.hpp>
#include <planning_like/msg/state.hpp>

enum class Mode { Idle, Driving };

// a switch that is no field's still works in a constant expression
constexpr int weight(Mode mode)
{
  switch (mode) {
    case Mode::Driving:
      return 2;
    default:
      return 1;
  }
}
static_assert(weight(Mode::Driving) == 2, "a switch in a constant expression");

int react(const std_msgs::msg::UInt8 & msg, const planning_like::msg::State & state, Mode mode)
{
  switch (msg.data) {
    case 1:
      return 2;
    default:
      break;
  }
  switch (state.state) {
    case planning_like::msg::State::DRIVING:
      return 3;
  }
  // not a field: stays what it is, so its cases keep their enumeration
  switch(mode) {
    case Mode::Driving:
      return 4;
    default:
      return std::to_string(msg.data).size();
  }
}
""")


def test_function_templates_deduce_a_vector_from_a_field(tmp_path):
    _assert_parses_clean(tmp_path, r"""
#include <cstdio>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <geometry_msgs/msg/point.hpp>
#include <nav_like/msg/path.hpp>
#include <std_msgs/msg/float64.hpp>

template <class T>
std::vector<T> resample(const std::vector<T> & points, double step);
template <class T>
double length(const std::vector<T> & points);

double run(const nav_like::msg::Path & path, const std_msgs::msg::Float64 & msg,
           rclcpp::Node & node)
{
  // what such a template returns converts on, and has a size
  std::vector<geometry_msgs::msg::Point> points = resample(path.points, 1.0);
  const auto coarse = resample(path.points, 2.0);
  // a field still passes through `...`
  std::printf("%f\n", msg.data);
  RCLCPP_INFO(node.get_logger(), "%f", msg.data);
  return length(path.points) + length(points) + coarse.size();
}
""")


def test_an_element_of_a_field_goes_into_sets_and_optionals(tmp_path):
    _assert_parses_clean(tmp_path, r"""
#include <optional>
#include <set>
#include <unordered_set>
#include <lanelet_like/lanelet.hpp>
#include <nav_like/msg/path.hpp>
#include <sensor_msgs/msg/laser_scan.hpp>

std::optional<lanelet_like::Polygon3d> first(
  const nav_like::msg::Path & path, std::set<long> & ids, std::unordered_set<long> & seen,
  sensor_msgs::msg::LaserScan & scan)
{
  // an element still binds to a reference of a number
  for (float & range : scan.ranges) {
    range = 0.0f;
  }
  for (const auto & point : path.points) {
    for (const auto & lane_id : point.lane_ids) {
      ids.insert(lane_id);
      seen.insert(lane_id);
    }
  }
  for (const auto & polygon : path.polygons) {
    return polygon;
  }
  return {};
}
""")


def test_classes_of_unknown_libraries_are_made_from_braced_lists(tmp_path):
    _assert_parses_clean(tmp_path, r"""
#include <geo_like/geometry.hpp>
#include <nav_like/msg/path.hpp>

geo_like::LineString2d segment(const nav_like::msg::Path & path, const geo_like::Point2d & p)
{
  const auto & a = path.points.front();
  const geo_like::LineString2d line{{a.x, a.y}, {a.x + 1.0, a.y}};
  const geo_like::LineString2d mixed = {p, {a.x, a.y}};
  geo_like::LineString2d copy = line;
  geo_like::LineString2d one(p);
  copy = {};
  return {{a.x, a.y}, p};
}
""")


def test_static_assertions_on_stand_ins_are_no_errors(tmp_path):
    # they hold in the package's real build; the model's types differ
    _assert_parses_clean(tmp_path, (
        '#include <cstdint>\n'
        '#include <type_traits>\n'
        '#include <sensor_msgs/msg/point_cloud2.hpp>\n'
        'static_assert(std::is_same<decltype(sensor_msgs::msg::PointCloud2()'
        '.height), uint32_t>::value, "height is 32 bits");\n'
        'template <class T> struct Buffer\n'
        '{\n'
        '  static_assert(sizeof(T) == 32, "a cloud is 32 bytes");\n'
        '};\n'
        'Buffer<sensor_msgs::msg::PointCloud2> buffer;\n'
        'void check() { static_assert(sizeof(buffer) > 0); }\n'))


def test_ros2_messages_keep_ros1s_pointer_names_and_qos_from_rmw(tmp_path):
    # rosidl still declares Ptr and ConstPtr (deprecated); a QoS is made
    # from an rmw profile through QoSInitialization::from_rmw
    _assert_parses_clean(tmp_path, (
        '#include <rclcpp/rclcpp.hpp>\n'
        '#include <sensor_msgs/msg/point_cloud2.hpp>\n'
        'void on_cloud(const sensor_msgs::msg::PointCloud2::ConstPtr & msg);\n'
        'sensor_msgs::msg::PointCloud2::Ptr copy;\n'
        'sensor_msgs::msg::PointCloud2::ConstWeakPtr last;\n'
        'rclcpp::QoS qos(rclcpp::QoSInitialization::from_rmw(\n'
        '  rmw_qos_profile_sensor_data), rmw_qos_profile_sensor_data);\n'))


def test_typed_iterators_of_unknown_classes_and_one_argument_to_msg(tmp_path):
    # OpenCV's `image.begin<ushort>()`; tf2::toMsg of a tf2 type where only
    # <tf2/convert.h> is included (the overload is in tf2_geometry_msgs)
    _assert_parses_clean(tmp_path, (
        '#include <algorithm>\n'
        '#include <vector>\n'
        '#include <opencv_like/core.hpp>\n'
        '#include <tf2/convert.h>\n'
        '#include <tf2/LinearMath/Quaternion.h>\n'
        '#include <geometry_msgs/Pose.h>\n'
        'void f(const opencv_like::Mat & image, const std::vector<double> & p,\n'
        '       const tf2::Quaternion & q)\n'
        '{\n'
        '  auto first = image.begin<unsigned short>();\n'
        '  auto last = std::unique(first, image.end<unsigned short>());\n'
        '  std::copy(p.begin(), p.end(), image.begin<double>());\n'
        '  geometry_msgs::Pose pose;\n'
        '  pose.orientation = tf2::toMsg(q);\n'
        '}\n'))


def test_a_constant_read_through_an_object_and_unknown_iterators(tmp_path):
    # `filter.UNKNOWN` (the package's struct) beside `Label::UNKNOWN` (a
    # message's constant); grid_map's iterator, of a library the model lacks
    _assert_parses_clean(tmp_path, (
        '#include <cstdint>\n'
        '#include <perception_like_msgs/msg/object_classification.hpp>\n'
        '#include <grid_map_like/iterators.hpp>\n'
        'struct Filter { bool UNKNOWN; bool CAR; };\n'
        'using Label = perception_like_msgs::msg::ObjectClassification;\n'
        'bool is_target(const Filter & filter, const uint8_t label)\n'
        '{\n'
        '  return (label == Label::UNKNOWN && filter.UNKNOWN) ||\n'
        '    (label == Label::CAR && filter.CAR);\n'
        '}\n'
        'void walk(const grid_map_like::GridMap & map)\n'
        '{\n'
        '  for (grid_map_like::GridMapIterator it(map); !it.isPastEnd();'
        ' ++it) {}\n'
        '  grid_map_like::GridMapIterator back(map);\n'
        '  back--;\n'
        '}\n'))


def test_messages_of_a_type_compare_as_generated_messages_do(tmp_path):
    # rosidl and gencpp give every message == and !=; a state kept to
    # publish only on change compares the new one with the last
    _assert_parses_clean(tmp_path, (
        '#include <memory>\n'
        '#include <optional>\n'
        '#include <adapi_like_msgs/msg/mrm_state.hpp>\n'
        '#include <legacy_msgs/ModeState.h>\n'
        'using MrmState = adapi_like_msgs::msg::MrmState;\n'
        'bool changed(const MrmState & now,\n'
        '             const std::shared_ptr<const MrmState> & last,\n'
        '             const std::optional<MrmState> & kept,\n'
        '             const legacy_msgs::ModeState & a,\n'
        '             const legacy_msgs::ModeStateConstPtr & b)\n'
        '{\n'
        '  return now != *last || kept != now || !(a == *b);\n'
        '}\n'))


def test_string_constants_and_members_taking_a_type_and_values(tmp_path):
    # a message's string constant (the stand-in knows only its name) against
    # a std::string; grid_map's `toImage<unsigned char, 3>(...)`, of a class
    # a repair declared, beside its type-only and value-only forms; Ogre's
    # begin with arguments; a field appended to a string; Boost.Asio's
    # older error_code forms
    _assert_parses_clean(tmp_path, r"""
#include <string>
#include <boost/asio.hpp>
#include <planning_like_msgs/msg/scenario.hpp>
#include <grid_like/converter.hpp>
using Scenario = planning_like_msgs::msg::Scenario;
bool driving(std::string & current, const grid_like::Map & map,
             const Scenario & scenario)
{
  grid_like::Converter::toImage<unsigned char, 3>(map, "layer", 16);
  grid_like::Converter::toImage<float>(map);
  grid_like::Converter::toImage<2>(map);
  map.begin("BaseWhiteNoLighting", 2);
  for (const auto & cell : map) {}
  current += scenario.current_scenario;
  boost::asio::io_service io;
  boost::system::error_code error;
  io.run(error);
  if (error) {
    current += error.message();
  }
  return current == Scenario::LANEDRIVING || Scenario::PARKING != current;
}
""", {
        ('type', 'grid_like::Converter'),
        ('member-template', 'grid_like::Converter::toImage')})


def test_an_all_caps_name_of_an_unknown_library_is_a_constant(tmp_path):
    # ceres' enumerators, one without an underscore, beside its classes
    _assert_parses_clean(tmp_path, (
        '#include <ceres_like/ceres.h>\n'
        'int configure(ceres_like::Problem & problem, bool cg)\n'
        '{\n'
        '  problem.setSolver(\n'
        '    cg ? ceres_like::CGNR : ceres_like::SPARSE_NORMAL_CHOLESKY);\n'
        '  const int type = ceres_like::CGNR;\n'
        '  return type;\n'
        '}\n'))


def test_every_form_of_rclcpps_logging_macros(tmp_path):
    # the stream forms build their text with an ostream
    _assert_parses_clean(tmp_path, (
        '#include <string>\n'
        '#include <rclcpp/rclcpp.hpp>\n'
        'void report(rclcpp::Node & node, const std::string & frame)\n'
        '{\n'
        '  RCLCPP_ERROR_STREAM_THROTTLE(node.get_logger(), *node.get_clock(),'
        ' 1000, "no transform from " << frame);\n'
        '  RCLCPP_DEBUG_STREAM_ONCE(node.get_logger(), "frame " << frame);\n'
        '  RCLCPP_FATAL_STREAM_EXPRESSION(node.get_logger(), frame.empty(),'
        ' "empty " << frame);\n'
        '  RCLCPP_WARN_SKIPFIRST_THROTTLE(node.get_logger(), '
        '*node.get_clock(), 500, "late %s", frame.c_str());\n'
        '  RCLCPP_INFO_FUNCTION(node.get_logger(), nullptr, "%d", 1);\n'
        '}\n'))


def test_a_field_compares_with_an_optional_of_its_type(tmp_path):
    # std::optional's own comparisons with its value, not the catch-all's
    _assert_parses_clean(tmp_path, (
        '#include <optional>\n'
        '#include <diag_like_msgs/msg/status.hpp>\n'
        'using Level = diag_like_msgs::msg::Status::_level_type;\n'
        'bool changed(const Level level, std::optional<Level> & last)\n'
        '{\n'
        '  if (level == last) return false;\n'
        '  last = level;\n'
        '  return last != level || level < 2;\n'
        '}\n'))
