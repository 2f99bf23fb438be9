# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The table of ROS APIs the analysis recognises: qualified name -> role.

This is data, not code. A call is recognised by the qualified name of the
*declaration* it calls (``ros::NodeHandle::advertise``), never by the spelling
of the object it is called on. Argument positions are 0-based and count only
the arguments written at the call site (not the object).

Sources: the API documentation and Debian's ROS 1 headers (Noetic)
and the public sources of rclcpp, image_common, message_filters,
realtime_tools, diagnostics and geometry2 (Humble, Jazzy, Rolling). Where
an overload set moves an argument between forms (the free rclcpp
functions), the argument is found by its type (``FIRST_STRING``, ...).
"""

from dataclasses import dataclass
from typing import Optional

# roles
PUBLISHER = 'publisher'            # a call that returns a publisher handle
SUBSCRIBER = 'subscriber'          # a call that returns a subscriber handle
TIMER = 'timer'                    # a call that registers a periodic callback
SERVICE = 'service'                # a call that registers a service server
PUBLISH = 'publish'                # a call that publishes through its object
RATE = 'rate'                      # the constructor of an adaptive-sleep object
RATE_SLEEP = 'rate_sleep'          # the adaptive sleep itself
DECLARED_PUBLISHER = 'declared_publisher'    # every object of the class
DECLARED_SUBSCRIBER = 'declared_subscriber'  # every object of the class
SYNC = 'sync'                      # a message_filters synchronizer
REGISTER_CALLBACK = 'register_callback'      # message_filters callbacks
ACTION_SERVER = 'action_server'
ACTION_CLIENT = 'action_client'
NODE_HANDLE = 'node_handle'        # a NodeHandle constructor
# returns its name argument resolved as the node (or handle) resolves it
# (``nh.resolveName("out")``): as a topic, that name in that namespace
NAME_RESOLVE = 'name_resolve'
# returns the node's fully qualified name (``ros::this_node::getName()``):
# as a name, the node's private namespace ``~``
NODE_FQN = 'node_fqn'
PRIVATE_HANDLE = 'private_handle'  # returns the node's private handle
PUBLIC_HANDLE = 'public_handle'    # returns the node's public handle
PARAM_READ = 'param_read'          # reads a parameter into a variable
NODE_NAME = 'node_name'            # names the node (ros::init, Node ctor)
SUB_NODE = 'sub_node'              # returns a handle in a sub-namespace
CLIENT = 'client'                  # a service client
# publishes from a timer of its own (ROS 2 diagnostic_updater::Updater)
TIMED_PUBLISHER = 'timed_publisher'
# clocks beyond ROS (see frontend/cpp/clocks.py)
SIGNAL_CONNECT = 'signal_connect'  # QObject::connect: a QTimer's timeout()
TIMER_PERIOD = 'timer_period'      # sets the period of a timer object
TIMER_SINGLE_SHOT = 'timer_single_shot'  # a QTimer that fires once
OBJECT_TIMER = 'object_timer'      # QObject::startTimer -> timerEvent()
TIMER_WAIT = 'timer_wait'          # boost::asio async_wait(handler)
DEADLINE_SLEEP = 'deadline_sleep'  # sleep_until(deadline)
# code hosted by a process (see frontend/cpp/hosted.py)
HOST_EVENT = 'host_event'          # a callback the host calls on its events
NODELET_LOAD = 'nodelet_load'      # a nodelet the process loads itself

# special argument positions
FIRST_STRING = 'first_string'      # the first argument of string type
FIRST_CALLBACK = 'first_callback'  # the first argument naming a function
# the first argument whose type is callable (a lambda, a bind result, a
# function pointer): for overload sets whose callback moves with the form
FIRST_CALLABLE = 'first_callable'
# every argument whose type is callable
ALL_CALLABLES = 'all_callables'
# the first argument that is a duration (std::chrono or rclcpp::Duration)
FIRST_DURATION = 'first_duration'

TF_MSG = 'tf2_msgs::TFMessage'
IMAGE_MSG = 'sensor_msgs::Image'
CAMERA_INFO_MSG = 'sensor_msgs::CameraInfo'


@dataclass(frozen=True)
class Api:
    """How one ROS API is used by the analysis."""

    role: str
    # argument holding the topic / service / action name
    name_arg: object = None
    # argument holding the callback
    callback_arg: object = None
    # fixed message type; None: from the explicit template argument or
    # the callback's parameter
    msg_type: Optional[str] = None
    # topics created implicitly by the API
    implicit_topics: tuple = ()
    # image_transport camera APIs also create `<dirname>/camera_info`
    camera: bool = False
    # the argument holding a period (a duration, or a rate in Hz): its
    # position or FIRST_DURATION
    period_arg: object = None
    # the public name the analysis reports for this API; default: the key
    label: Optional[str] = None
    # NODE_NAME: the argument holding the node's namespace
    namespace_arg: Optional[int] = None
    # PARAM_READ: the call returns the value (``declare_parameter``)
    # rather than writing it to its second argument (``getParam``)
    returns_value: bool = False
    # PARAM_READ: ROS 2 parameters always belong to the node itself
    node_private: bool = False
    # PUBLISHER/SUBSCRIBER: the argument holding the NodeHandle, for the
    # APIs that take it as one (else the call's object is the handle)
    nh_arg: Optional[int] = None
    # PUBLISHER: when this is the only argument, the object wraps the
    # publisher passed there (ROS 2 realtime_tools::RealtimePublisher)
    wraps_arg: Optional[int] = None
    # TIMED_PUBLISHER: the period in seconds when the call gives none
    default_period: Optional[float] = None
    # a bare number given as period_arg counts this many seconds (a Qt
    # interval is in milliseconds)
    period_unit: float = 1.0
    # generic publishers/subscriptions: the argument naming the type as a
    # string ("std_msgs/msg/String"), which gives the message type
    type_name_arg: Optional[int] = None
    # SYNC: the argument holding the filter's one input, where the call
    # has one: tf's filters take (input, tf, frame, ...) or (tf, frame,
    # ...), the tf object never an input
    input_filter_arg: Optional[int] = None
    # the argument whose type is the message (rclcpp::wait_for_message's
    # output message)
    msg_type_arg: Optional[int] = None
    # PUBLISHER: the arguments holding callbacks run when a subscriber
    # connects or disconnects (a lazy node subscribes to its inputs there)
    status_callback_args: tuple = ()
    # ACTION_SERVER: the topics, under the action's name, that the server
    # subscribes to (ROS 1 actionlib's goal and cancel)
    action_inputs: tuple = ()


NH = 'ros::NodeHandle::'
# what a ROS 1 actionlib server subscribes to under its action's name (its
# status, feedback and result publishers are the library's, see
# docs/limitations.md)
ACTIONLIB_SERVER_INPUTS = ('goal', 'cancel')


# ROS 2: the callback a publisher's options hold that runs when a
# subscription matches it or leaves (`options.event_callbacks.
# matched_callback`): ROS 1's SubscriberStatusCallback, where a lazy node
# makes its subscriptions
PUBLISHER_MATCHED_CALLBACK = 'rclcpp::PublisherEventCallbacks::matched_callback'


def _ros2_node_methods(prefix):
    """The create_* methods of rclcpp::Node and LifecycleNode."""
    return {
        prefix + 'create_publisher': Api(PUBLISHER, name_arg=0),
        prefix + 'create_subscription': Api(
            SUBSCRIBER, name_arg=0, callback_arg=2),
        prefix + 'create_generic_publisher': Api(
            PUBLISHER, name_arg=0, type_name_arg=1),
        prefix + 'create_generic_subscription': Api(
            SUBSCRIBER, name_arg=0, callback_arg=3, type_name_arg=1),
        prefix + 'create_wall_timer': Api(
            TIMER, callback_arg=1, period_arg=0),
        prefix + 'create_timer': Api(TIMER, callback_arg=1, period_arg=0),
        prefix + 'create_service': Api(SERVICE, name_arg=0, callback_arg=1),
        prefix + 'create_client': Api(CLIENT, name_arg=0),
        prefix + 'create_sub_node': Api(SUB_NODE, name_arg=0),
        # value = declare_parameter("topic", "scan")
        prefix + 'declare_parameter': Api(
            PARAM_READ, name_arg=0, returns_value=True, node_private=True),
        # get_parameter("topic").as_string(); get_parameter("topic", value)
        prefix + 'get_parameter': Api(
            PARAM_READ, name_arg=0, node_private=True),
        prefix + 'get_parameter_or': Api(
            PARAM_READ, name_arg=0, node_private=True),
    }


def _asio_timer(timer_class):
    """The methods of a boost::asio timer class template."""
    method = timer_class + '::'
    short = timer_class.rsplit('::', 1)[1]
    # (io, expiry): a duration, or a time point, which gives no period
    period = Api(TIMER_PERIOD, period_arg=1, label=timer_class)
    return {
        method + short: period,
        method + 'expires_after': Api(
            TIMER_PERIOD, period_arg=0, label=timer_class),
        method + 'expires_from_now': Api(
            TIMER_PERIOD, period_arg=0, label=timer_class),
        # expires_at(expiry() + period)
        method + 'expires_at': Api(
            TIMER_PERIOD, period_arg=0, label=timer_class),
        method + 'async_wait': Api(
            TIMER_WAIT, callback_arg=0, label=timer_class),
    }


def _polling_subscriber(polling_class):
    """A polling subscriber: an input the node reads when it runs.

    It has no callback: (node, topic, qos) to the constructor or to the
    static create_subscription.
    """
    short = polling_class.rsplit('::', 1)[1]
    api = Api(SUBSCRIBER, name_arg=FIRST_STRING, label=polling_class)
    return {f'{polling_class}::{short}': api,
            f'{polling_class}::create_subscription': api}


IT = 'image_transport::ImageTransport::'

CALLS = {
    # roscpp
    NH + 'advertise': Api(PUBLISHER, name_arg=0, status_callback_args=(2, 3)),
    NH + 'subscribe': Api(SUBSCRIBER, name_arg=0, callback_arg=2),
    NH + 'createTimer': Api(TIMER, callback_arg=1, period_arg=0),
    NH + 'createWallTimer': Api(TIMER, callback_arg=1, period_arg=0),
    NH + 'createSteadyTimer': Api(TIMER, callback_arg=1, period_arg=0),
    NH + 'advertiseService': Api(SERVICE, name_arg=0, callback_arg=1),
    NH + 'serviceClient': Api(CLIENT, name_arg=0),
    # one message from a temporary subscription: an input all the same
    'ros::topic::waitForMessage': Api(SUBSCRIBER, name_arg=0),
    'ros::service::createClient': Api(CLIENT, name_arg=0),
    'ros::init': Api(NODE_NAME, name_arg=2),
    NH + 'NodeHandle': Api(NODE_HANDLE),
    NH + 'resolveName': Api(NAME_RESOLVE, name_arg=0),
    # expand_topic_or_service_name(name, node_name, namespace_,
    # is_service): the name in the namespace passed (the node's own)
    'rclcpp::expand_topic_or_service_name': Api(NAME_RESOLVE, name_arg=0),
    'rclcpp::node_interfaces::NodeTopicsInterface::resolve_topic_name': Api(
        NAME_RESOLVE, name_arg=0),
    # the clients of another node's parameters: on_parameter_event
    # subscribes the client's node to /parameter_events
    **{client + '::on_parameter_event': Api(
        SUBSCRIBER, callback_arg=FIRST_CALLABLE,
        msg_type='rcl_interfaces::msg::ParameterEvent',
        implicit_topics=('/parameter_events',))
       for client in ('rclcpp::AsyncParametersClient',
                      'rclcpp::SyncParametersClient')},
    'ros::this_node::getName': Api(NODE_FQN),
    'rclcpp::Node::get_fully_qualified_name': Api(NODE_FQN),
    'rclcpp_lifecycle::LifecycleNode::get_fully_qualified_name': Api(NODE_FQN),
    'rclcpp::node_interfaces::NodeBaseInterface::get_fully_qualified_name':
        Api(NODE_FQN),
    NH + 'param': Api(PARAM_READ, name_arg=0),
    NH + 'getParam': Api(PARAM_READ, name_arg=0),
    NH + 'getParamCached': Api(PARAM_READ, name_arg=0),
    'ros::param::param': Api(PARAM_READ, name_arg=0),
    'ros::param::get': Api(PARAM_READ, name_arg=0),
    'ros::Publisher::publish': Api(PUBLISH),
    'ros::Rate::Rate': Api(RATE, period_arg=0),
    'ros::WallRate::WallRate': Api(RATE, period_arg=0),
    'ros::Rate::sleep': Api(RATE_SLEEP),
    'ros::WallRate::sleep': Api(RATE_SLEEP),
    # image_transport
    IT + 'ImageTransport': Api(NODE_HANDLE),
    IT + 'advertise': Api(PUBLISHER, name_arg=0, msg_type=IMAGE_MSG,
                          status_callback_args=(2, 3)),
    IT + 'advertiseCamera': Api(
        PUBLISHER, name_arg=0, msg_type=IMAGE_MSG, camera=True,
        status_callback_args=(2, 3, 4, 5)),
    IT + 'subscribe': Api(
        SUBSCRIBER, name_arg=0, callback_arg=2, msg_type=IMAGE_MSG),
    IT + 'subscribeCamera': Api(
        SUBSCRIBER, name_arg=0, callback_arg=2, msg_type=IMAGE_MSG,
        camera=True),
    'image_transport::Publisher::publish': Api(PUBLISH),
    'image_transport::CameraPublisher::publish': Api(PUBLISH),
    # a transport's plugin interface, which ImageTransport and republish
    # call through: (handle, base_topic, ...); ROS 1 takes a queue size
    # before the callback, ROS 2 none
    'image_transport::PublisherPlugin::advertise': Api(
        PUBLISHER, name_arg=1, nh_arg=0, msg_type=IMAGE_MSG,
        status_callback_args=(3, 4)),
    'image_transport::PublisherPlugin::publish': Api(PUBLISH),
    'image_transport::SubscriberPlugin::subscribe': Api(
        SUBSCRIBER, name_arg=1, nh_arg=0, callback_arg=FIRST_CALLBACK,
        msg_type=IMAGE_MSG),
    # image_transport (ROS 2) free functions: (node, base_topic, ...)
    'image_transport::create_publisher': Api(
        PUBLISHER, name_arg=1, msg_type='sensor_msgs::msg::Image'),
    'image_transport::create_camera_publisher': Api(
        PUBLISHER, name_arg=1, msg_type='sensor_msgs::msg::Image',
        camera=True),
    # create_subscription(node, base_topic, callback, transport, qos)
    'image_transport::create_subscription': Api(
        SUBSCRIBER, name_arg=1, callback_arg=2,
        msg_type='sensor_msgs::msg::Image'),
    'image_transport::create_camera_subscription': Api(
        SUBSCRIBER, name_arg=1, callback_arg=2,
        msg_type='sensor_msgs::msg::Image', camera=True),
    # a message_filters input: (node, base_topic, transport)
    'image_transport::SubscriberFilter::SubscriberFilter': Api(
        SUBSCRIBER, name_arg=1, msg_type='sensor_msgs::msg::Image',
        label='image_transport::SubscriberFilter'),
    'image_transport::SubscriberFilter::subscribe': Api(
        SUBSCRIBER, name_arg=1, msg_type='sensor_msgs::msg::Image',
        label='image_transport::SubscriberFilter'),
    # tf / tf2_ros: the broadcasters publish through sendTransform
    'tf::TransformBroadcaster::sendTransform': Api(PUBLISH),
    'tf2_ros::TransformBroadcaster::sendTransform': Api(PUBLISH),
    'tf2_ros::StaticTransformBroadcaster::sendTransform': Api(PUBLISH),
    # message_filters
    'message_filters::Subscriber::Subscriber': Api(
        SUBSCRIBER, name_arg=1, nh_arg=0, label='message_filters::Subscriber'),
    'message_filters::Subscriber::subscribe': Api(
        SUBSCRIBER, name_arg=1, nh_arg=0, label='message_filters::Subscriber'),
    'message_filters::Synchronizer::Synchronizer': Api(SYNC),
    'message_filters::TimeSynchronizer::TimeSynchronizer': Api(SYNC),
    'message_filters::Synchronizer::connectInput': Api(SYNC),
    'message_filters::TimeSynchronizer::connectInput': Api(SYNC),
    # tf's filters pass on what their input filter gives, once its frame
    # transforms: (input filter, tf, target frame, queue, ...)
    'tf::MessageFilter::MessageFilter': Api(SYNC, input_filter_arg=0),
    'tf::MessageFilter::connectInput': Api(SYNC),
    'tf2_ros::MessageFilter::MessageFilter': Api(SYNC, input_filter_arg=0),
    'tf2_ros::MessageFilter::connectInput': Api(SYNC),
    'message_filters::SimpleFilter::registerCallback': Api(
        REGISTER_CALLBACK, callback_arg=0),
    'message_filters::Synchronizer::registerCallback': Api(
        REGISTER_CALLBACK, callback_arg=0),
    # rclcpp::ParameterEventHandler: its callbacks run on /parameter_events
    'rclcpp::ParameterEventHandler::add_parameter_callback': Api(
        REGISTER_CALLBACK, callback_arg=1),
    'rclcpp::ParameterEventHandler::add_parameter_event_callback': Api(
        REGISTER_CALLBACK, callback_arg=0),
    # nodelet_topic_tools' lazy nodelet base: advertise<M>(nh, topic, queue,
    # latch), which calls the nodelet's subscribe() when a subscriber
    # connects (a nodelet runs all its methods: subscribe() is among them)
    'nodelet_topic_tools::NodeletLazy::advertise': Api(
        PUBLISHER, name_arg=1, nh_arg=0),
    # realtime_tools: the constructor (or init) advertises the topic
    # ROS 1: (nh, topic, queue); ROS 2: (publisher), which it wraps
    'realtime_tools::RealtimePublisher::RealtimePublisher': Api(
        PUBLISHER, name_arg=1, wraps_arg=0, nh_arg=0,
        label='realtime_tools::RealtimePublisher'),
    'realtime_tools::RealtimePublisher::init': Api(
        PUBLISHER, name_arg=1, nh_arg=0,
        label='realtime_tools::RealtimePublisher'),
    'realtime_tools::RealtimePublisher::unlockAndPublish': Api(PUBLISH),
    # realtime_tools (ROS 2, Jazzy+): the publish site without trylock
    'realtime_tools::RealtimePublisher::try_publish': Api(PUBLISH),
    'realtime_tools::RealtimePublisher::tryPublish': Api(PUBLISH),
    # diagnostic_updater publishes /diagnostics when updated
    'diagnostic_updater::Updater::update': Api(PUBLISH),
    'diagnostic_updater::Updater::force_update': Api(PUBLISH),
    'diagnostic_updater::Updater::broadcast': Api(PUBLISH),
    # ROS 2: Updater(node, period = 1.0) publishes from its own timer
    'diagnostic_updater::Updater::Updater': Api(
        TIMED_PUBLISHER, period_arg=1, default_period=1.0,
        label='diagnostic_updater::Updater'),
    # actionlib: recorded as actions, their callbacks are roots
    'actionlib::SimpleActionServer::SimpleActionServer': Api(
        ACTION_SERVER, name_arg=FIRST_STRING, callback_arg=FIRST_CALLBACK,
        label='actionlib::SimpleActionServer',
        action_inputs=ACTIONLIB_SERVER_INPUTS),
    'actionlib::ActionServer::ActionServer': Api(
        ACTION_SERVER, name_arg=FIRST_STRING, callback_arg=FIRST_CALLBACK,
        label='actionlib::ActionServer',
        action_inputs=ACTIONLIB_SERVER_INPUTS),
    'actionlib::SimpleActionServer::registerGoalCallback': Api(
        ACTION_SERVER, callback_arg=0, label='actionlib::SimpleActionServer'),
    'actionlib::SimpleActionServer::registerPreemptCallback': Api(
        ACTION_SERVER, callback_arg=0, label='actionlib::SimpleActionServer'),
    'actionlib::SimpleActionClient::SimpleActionClient': Api(
        ACTION_CLIENT, name_arg=FIRST_STRING,
        label='actionlib::SimpleActionClient'),
    'actionlib::ActionClient::ActionClient': Api(
        ACTION_CLIENT, name_arg=FIRST_STRING, label='actionlib::ActionClient'),
    # rclcpp (ROS 2): Node and LifecycleNode share the method shapes
    **_ros2_node_methods('rclcpp::Node::'),
    **_ros2_node_methods('rclcpp_lifecycle::LifecycleNode::'),
    'rclcpp::Node::Node': Api(NODE_NAME, name_arg=0, namespace_arg=1),
    'rclcpp::Node::make_shared': Api(NODE_NAME, name_arg=0, namespace_arg=1),
    'rclcpp_lifecycle::LifecycleNode::LifecycleNode': Api(
        NODE_NAME, name_arg=0, namespace_arg=1),
    'rclcpp_lifecycle::LifecycleNode::make_shared': Api(
        NODE_NAME, name_arg=0, namespace_arg=1),
    # (node, topic, qos) and (parameters, topics, topic, qos)
    'rclcpp::create_publisher': Api(PUBLISHER, name_arg=FIRST_STRING),
    'rclcpp::create_subscription': Api(
        SUBSCRIBER, name_arg=FIRST_STRING, callback_arg=FIRST_CALLABLE),
    # (node, clock, period, callback) and, Jazzy+, (clock, period,
    # callback, group, node_base, node_timers)
    'rclcpp::create_timer': Api(
        TIMER, callback_arg=FIRST_CALLABLE, period_arg=FIRST_DURATION),
    # create_wall_timer(period, callback, group, node_base*, node_timers*)
    'rclcpp::create_wall_timer': Api(TIMER, callback_arg=1, period_arg=0),
    # create_service<S>(node_base, node_services, name, callback, qos, group)
    'rclcpp::create_service': Api(SERVICE, name_arg=2, callback_arg=3),
    # create_client<S>(node_base, node_graph, node_services, name, qos, group)
    'rclcpp::create_client': Api(CLIENT, name_arg=3),
    # create_generic_*(topics_interface, name, type, qos[, callback])
    'rclcpp::create_generic_publisher': Api(
        PUBLISHER, name_arg=1, type_name_arg=2),
    'rclcpp::create_generic_subscription': Api(
        SUBSCRIBER, name_arg=1, callback_arg=4, type_name_arg=2),
    # wait_for_message(out, node, topic, ...): a temporary subscription
    # (the form taking an existing subscription names no topic)
    'rclcpp::wait_for_message': Api(
        SUBSCRIBER, name_arg=FIRST_STRING, msg_type_arg=0),
    'rclcpp::Publisher::publish': Api(PUBLISH),
    'rclcpp::GenericPublisher::publish': Api(PUBLISH),
    'rclcpp_lifecycle::LifecyclePublisher::publish': Api(PUBLISH),
    # Humble: Rate/WallRate are GenericRate<Clock>; Jazzy+: classes
    'rclcpp::GenericRate::GenericRate': Api(RATE, period_arg=0),
    'rclcpp::Rate::Rate': Api(RATE, period_arg=0),
    'rclcpp::WallRate::WallRate': Api(RATE, period_arg=0),
    'rclcpp::GenericRate::sleep': Api(RATE_SLEEP),
    'rclcpp::Rate::sleep': Api(RATE_SLEEP),
    'rclcpp::WallRate::sleep': Api(RATE_SLEEP),
    # Rolling: ROSRate (RCL_ROS_TIME) derives from Rate like WallRate
    'rclcpp::ROSRate::ROSRate': Api(RATE, period_arg=0),
    'rclcpp::ROSRate::sleep': Api(RATE_SLEEP),
    # rclcpp_action::create_server<A>(node, name, goal, cancel, accepted)
    # and the node-interfaces form (base, clock, logging, waitables, name,
    # goal, cancel, accepted)
    'rclcpp_action::create_server': Api(
        ACTION_SERVER, name_arg=FIRST_STRING, callback_arg=ALL_CALLABLES),
    'rclcpp_action::create_client': Api(
        ACTION_CLIENT, name_arg=FIRST_STRING),
    # rclcpp timers made directly, then added to the node's timers
    # interface: GenericTimer(clock, period, callback, context),
    # WallTimer(period, callback, context)
    'rclcpp::GenericTimer::GenericTimer': Api(
        TIMER, callback_arg=FIRST_CALLABLE, period_arg=FIRST_DURATION,
        label='rclcpp::GenericTimer'),
    'rclcpp::WallTimer::WallTimer': Api(
        TIMER, callback_arg=FIRST_CALLABLE, period_arg=FIRST_DURATION,
        label='rclcpp::WallTimer'),
    # Qt: a QTimer calls what its timeout() signal is connected to every
    # interval (in ms), unless it is single-shot; QObject::startTimer
    # calls the object's timerEvent()
    'QObject::connect': Api(SIGNAL_CONNECT, label='QTimer'),
    'QTimer::start': Api(TIMER_PERIOD, period_arg=0, period_unit=0.001),
    'QTimer::setInterval': Api(
        TIMER_PERIOD, period_arg=0, period_unit=0.001),
    'QTimer::setSingleShot': Api(TIMER_SINGLE_SHOT),
    'QObject::startTimer': Api(OBJECT_TIMER, period_arg=0, period_unit=0.001),
    # boost::asio: a handler that arms its timer again runs periodically;
    # the period comes from the constructor or the expires_* calls
    **_asio_timer('boost::asio::basic_waitable_timer'),
    **_asio_timer('boost::asio::basic_deadline_timer'),
    # a loop sleeping until a deadline it advances by a fixed period runs
    # at that period (see frontend/cpp/clocks.py)
    'std::this_thread::sleep_until': Api(DEADLINE_SLEEP),
    'boost::this_thread::sleep_until': Api(DEADLINE_SLEEP),
    # ROS 2's clock (Jazzy+): sleeps until a rclcpp::Time
    'rclcpp::Clock::sleep_until': Api(DEADLINE_SLEEP),
    # Autoware's utilities (a library outside Autoware's source workspace)
    **_polling_subscriber('autoware_utils::InterProcessPollingSubscriber'),
    **_polling_subscriber(
        'autoware::universe_utils::InterProcessPollingSubscriber'),
    # nodelet handles
    'nodelet::Nodelet::getNodeHandle': Api(PUBLIC_HANDLE),
    'nodelet::Nodelet::getMTNodeHandle': Api(PUBLIC_HANDLE),
    'nodelet::Nodelet::getPrivateNodeHandle': Api(PRIVATE_HANDLE),
    'nodelet::Nodelet::getMTPrivateNodeHandle': Api(PRIVATE_HANDLE),
    # nodelet::Loader::load(name, type, remappings, my_argv): an instance
    # of the nodelet `type` under the name `name`
    'nodelet::Loader::load': Api(NODELET_LOAD, name_arg=0, type_name_arg=1),
    # Gazebo (gazebo_ros_pkgs' plugins): gzserver calls these callbacks at
    # the start / end of every simulation step (plugin_hosts.py)
    'gazebo::event::Events::ConnectWorldUpdateBegin': Api(
        HOST_EVENT, callback_arg=0),
    'gazebo::event::Events::ConnectWorldUpdateEnd': Api(
        HOST_EVENT, callback_arg=0),
    'gazebo::event::Events::ConnectBeforePhysicsUpdate': Api(
        HOST_EVENT, callback_arg=0),
}

# classes whose every object (variable, field, pointee) is a publisher or a
# subscriber with implicit topics
DECLARED = {
    'tf::TransformBroadcaster': Api(
        DECLARED_PUBLISHER, msg_type=TF_MSG, implicit_topics=('/tf',)),
    'tf2_ros::TransformBroadcaster': Api(
        DECLARED_PUBLISHER, msg_type=TF_MSG, implicit_topics=('/tf',)),
    'tf2_ros::StaticTransformBroadcaster': Api(
        DECLARED_PUBLISHER, msg_type=TF_MSG, implicit_topics=('/tf_static',)),
    'diagnostic_updater::Updater': Api(
        DECLARED_PUBLISHER, msg_type='diagnostic_msgs::DiagnosticArray',
        implicit_topics=('/diagnostics',)),
    'tf::TransformListener': Api(
        DECLARED_SUBSCRIBER, msg_type=TF_MSG,
        implicit_topics=('/tf', '/tf_static')),
    'tf2_ros::TransformListener': Api(
        DECLARED_SUBSCRIBER, msg_type=TF_MSG,
        implicit_topics=('/tf', '/tf_static')),
    # made by the user's code, unlike the node's own parameter services
    'rclcpp::ParameterEventHandler': Api(
        DECLARED_SUBSCRIBER, msg_type='rcl_interfaces::msg::ParameterEvent',
        implicit_topics=('/parameter_events',)),
}

# factory functions whose template argument names the constructed class, so
# that `std::make_shared<realtime_tools::RealtimePublisher<M>>(nh, "t", 1)`
# is read like the constructor it forwards to
FORWARDING_FACTORIES = frozenset({
    'std::make_shared', 'std::make_unique', 'std::allocate_shared',
    'boost::make_shared', 'boost::allocate_shared',
})
FORWARDING_FACTORY_NAMES = frozenset(
    name.rsplit('::', 1)[1] for name in FORWARDING_FACTORIES)

# methods returning the topic name of the publisher or subscription they
# are called on: a string set to one holds the name that endpoint was made
# with (as the middleware resolved it)
TOPIC_NAME_GETTERS = frozenset({
    'ros::Publisher::getTopic', 'ros::Subscriber::getTopic',
    'rclcpp::PublisherBase::get_topic_name',
    'rclcpp::SubscriptionBase::get_topic_name',
})

# functions that are roots of a node by their name alone
MAIN_FUNCTION = 'main'
NODELET_INIT_METHOD = 'onInit'


# methods whose name alone says what a call does where the AST cannot tell:
# on an object of a template parameter's type, or in code the parse lost
# (frontend/cpp/token_facts.py). Only the endpoint-creating ones, which no
# other library of the ROS world names so, and only with at least as many
# arguments as the ROS API takes (a serial protocol's `subscribe(rate)` is
# no subscription): name -> (ROS 1 API, ROS 2 API, fewest arguments)
QT_CONNECT = 'QObject::connect'
METHODS_BY_NAME = {
    'advertise': ('ros::NodeHandle::advertise', None, 2),
    'subscribe': ('ros::NodeHandle::subscribe', None, 3),
    'createTimer': ('ros::NodeHandle::createTimer', None, 2),
    'createWallTimer': ('ros::NodeHandle::createWallTimer', None, 2),
    'createSteadyTimer': ('ros::NodeHandle::createSteadyTimer', None, 2),
    'advertiseService': ('ros::NodeHandle::advertiseService', None, 2),
    'create_publisher': (None, 'rclcpp::Node::create_publisher', 2),
    'create_subscription': (None, 'rclcpp::Node::create_subscription', 3),
    'create_generic_publisher': (
        None, 'rclcpp::Node::create_generic_publisher', 3),
    'create_generic_subscription': (
        None, 'rclcpp::Node::create_generic_subscription', 4),
    'create_wall_timer': (None, 'rclcpp::Node::create_wall_timer', 2),
    'create_timer': (None, 'rclcpp::Node::create_timer', 2),
    'create_service': (None, 'rclcpp::Node::create_service', 2),
    # a publisher of a template's message type (a wrapper's)
    'publish': ('ros::Publisher::publish', 'rclcpp::Publisher::publish', 1),
    # Qt's connect() called in a class whose QObject base the parse could
    # not see (a widget class the model lacks): only a connection of
    # QTimer's timeout() signal is taken for it (any other `connect` may be
    # the package's own)
    'connect': (QT_CONNECT, QT_CONNECT, 3),
}
# `rate.sleep()` on an object known to be a rate
RATE_SLEEP_BY_NAME = ('ros::Rate::sleep', 'rclcpp::Rate::sleep')


def dependent_method(method, *, ros2, arguments=None):
    """The API a call of `method` stands for, by its name alone, or None.

    :param arguments: how many arguments the call writes (None: not known)
    """
    names = METHODS_BY_NAME.get(method)
    if names is None:
        return None
    ros1_name, ros2_name, fewest = names
    if arguments is not None and arguments < fewest:
        return None
    name = ros2_name if ros2 else ros1_name
    return name if name in CALLS else None


def methods_named(method):
    """The qualified APIs of the table whose method is called `method`."""
    return [name for name in CALLS if name.rsplit('::', 1)[-1] == method
            and name.count('::') >= 2]


def joins_after_node_name(value, rest):
    """Whether `rest` may follow `value` in a name joined by the code.

    A string holding the node's own name (``~``, role NODE_FQN) makes
    ``/ns/node`` + ``_x``: no ROS name says that (``~_x`` is
    ``/ns/node/_x``); only ``/x`` or nothing may follow.
    """
    return value != '~' or not rest or rest.startswith('/')


def lookup_call(qualified_name):
    """Return the :class:`Api` for a called declaration, or None."""
    return CALLS.get(qualified_name)


def api_label(qualified_name):
    """Return the name under which an API is reported."""
    api = CALLS.get(qualified_name) or DECLARED.get(qualified_name)
    if api is not None and api.label:
        return api.label
    return qualified_name
