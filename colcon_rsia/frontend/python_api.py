# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The table of Python ROS APIs the analysis recognises: name -> role.

This is data, not code, like :mod:`colcon_rsia.frontend.ros_api` (whose role
constants it reuses). A call is recognised by the *canonical dotted name*
of what it calls, found through the module's imports, never by the
spelling at the call site: ``from rclpy.node import Node`` then
``class Talker(Node)`` and ``self.create_publisher(...)`` is
``rclpy.node.Node.create_publisher``; ``import rospy as rp`` then
``rp.Publisher(...)`` is ``rospy.Publisher``. Names the libraries re-export
from inner modules (``rospy.topics.Publisher``) are mapped to one canonical
name by :data:`ALIASES`.

Arguments are ``(position, keyword)`` pairs: the 0-based position among the
positional arguments written at the call site (not counting the object a
method is called on), and the keyword that may name it instead; either may
be None.

The API names reported in summaries (the ``api`` field) are the keys below:

========================================  ===================================
publishers                                ``rospy.Publisher``,
                                          ``rclpy.node.Node.create_publisher``
                                          (and ``create_lifecycle_publisher``
                                          of a lifecycle node),
                                          ``tf2_ros.TransformBroadcaster`` and
                                          ``tf.TransformBroadcaster`` (/tf),
                                          ``tf2_ros.StaticTransformBroadcaster``
                                          (/tf_static),
                                          ``diagnostic_updater.Updater``
                                          (/diagnostics; with a node
                                          argument (ROS 2) it publishes
                                          from a timer of its own)
publish sites                             ``rospy.Publisher.publish``,
                                          ``rclpy.publisher.Publisher.publish``,
                                          ``<broadcaster>.sendTransform``,
                                          ``Updater.update`` /
                                          ``force_update`` / ``broadcast`` /
                                          ``publish``,
                                          ``DiagnosedPublisher.publish`` (the
                                          publisher it wraps);
                                          ``publish`` / ``sendTransform`` on an
                                          object of unknown type
subscribers                               ``rospy.Subscriber``,
                                          ``rclpy.node.Node.create_subscription``,
                                          ``message_filters.Subscriber`` (ROS 1
                                          ``(topic, Type)`` and ROS 2
                                          ``(node, Type, topic)``),
                                          ``rospy.wait_for_message`` and
                                          ``rclpy.wait_for_message.wait_for_message``
                                          (one-shot subscriptions: inputs),
                                          ``tf2_ros.TransformListener``,
                                          ``tf.TransformListener`` (/tf and
                                          /tf_static),
                                          ``interactive_markers.``
                                          ``InteractiveMarkerServer``
                                          (<topic_ns>/feedback)
timers                                    ``rospy.Timer`` (a ``rospy.Duration``),
                                          ``rclpy.node.Node.create_timer``
                                          (seconds)
rate objects and their adaptive sleep     ``rospy.Rate`` + ``rospy.Rate.sleep``,
                                          ``rclpy.node.Node.create_rate`` +
                                          ``rclpy.timer.Rate.sleep``
services                                  ``rospy.Service``,
                                          ``rclpy.node.Node.create_service``
actions                                   ``rclpy.action.ActionServer`` /
                                          ``ActionClient``,
                                          ``actionlib.SimpleActionServer`` /
                                          ``ActionServer`` /
                                          ``SimpleActionClient`` /
                                          ``ActionClient``
message_filters synchronisers             ``message_filters.TimeSynchronizer``,
                                          ``ApproximateTimeSynchronizer``,
                                          ``Cache``; ``registerCallback``
callbacks of a subscription               ``InteractiveMarkerServer.insert`` /
                                          ``setCallback``,
                                          ``MenuHandler.insert``
sleeps that do not adapt (recognised so   ``rospy.sleep``, ``time.sleep``
that they are never taken for a Rate)
parameter reads (a topic name may come    ``rospy.get_param``,
from one)                                 ``rclpy.node.Node.declare_parameter``,
                                          ``declare_parameters``,
                                          ``rclpy.node.Node.get_parameter``
========================================  ===================================

Sources: the API documentation of rospy and actionlib (noetic), rclpy
(humble/jazzy/rolling), message_filters, tf2_ros and tf.
"""

from dataclasses import dataclass
from typing import Optional

from colcon_rsia.frontend.ros_api import ACTION_CLIENT
from colcon_rsia.frontend.ros_api import ACTION_SERVER
from colcon_rsia.frontend.ros_api import NODE_HANDLE
from colcon_rsia.frontend.ros_api import PARAM_READ
from colcon_rsia.frontend.ros_api import PUBLISH
from colcon_rsia.frontend.ros_api import PUBLISHER
from colcon_rsia.frontend.ros_api import RATE
from colcon_rsia.frontend.ros_api import RATE_SLEEP
from colcon_rsia.frontend.ros_api import REGISTER_CALLBACK
from colcon_rsia.frontend.ros_api import SERVICE
from colcon_rsia.frontend.ros_api import SUBSCRIBER
from colcon_rsia.frontend.ros_api import SYNC
from colcon_rsia.frontend.ros_api import TF_MSG
from colcon_rsia.frontend.ros_api import TIMER

# roles only Python needs
SLEEP = 'sleep'                    # a plain sleep: never paces a loop
SERVICE_CLIENT = 'service_client'  # no graph edge, no input
PARTIAL = 'partial'                # functools.partial: binds a callback

# how a period argument is written
SECONDS = 'seconds'     # a number of seconds (or a Duration object)
DURATION = 'duration'   # a Duration object (a bare number: seconds)
HZ = 'hz'               # a frequency

NODE_CLASS = 'rclpy.node.Node'
DIAGNOSTICS_MSG = 'diagnostic_msgs::DiagnosticArray'
MARKER_FEEDBACK_MSG = 'visualization_msgs::InteractiveMarkerFeedback'


@dataclass(frozen=True)
class PyApi:
    """How one Python ROS API is used by the analysis."""

    role: str
    # (position, keyword) of the topic / service / action name
    name: Optional[tuple] = None
    # (position, keyword) of the message / service / action type
    msg_type_arg: Optional[tuple] = None
    # (position, keyword) of the callback
    callback: Optional[tuple] = None
    # further callbacks (action servers), as (position, keyword) pairs
    extra_callbacks: tuple = ()
    # rospy's callback_args: bound to the callback's second parameter
    callback_args: Optional[tuple] = None
    # (position, keyword) of the period / rate and how it is written
    period: Optional[tuple] = None
    period_unit: Optional[str] = None
    # fixed message type and topics created implicitly (tf)
    msg_type: Optional[str] = None
    implicit_topics: tuple = ()
    # (position, keyword) of a synchroniser's input filter(s)
    inputs: Optional[tuple] = None
    # the canonical type of the object the call returns, when not the
    # called class itself
    returns: Optional[str] = None
    # APIs of both ROS 1 and ROS 2 whose arguments differ: (name,
    # msg_type) of the ROS 1 form, used when a keyword only the ROS 1 form
    # has is given (ros1_keywords), or none of the ROS 2 form's
    # (ros2_keywords) and the first argument is a string or fewer than
    # ros2_arity positional arguments are given (message_filters'
    # Subscriber(topic, Type) and Subscriber(node, Type, topic))
    ros1_form: Optional[tuple] = None
    ros1_keywords: tuple = ()
    ros2_keywords: tuple = ()
    ros2_arity: int = 0
    # SUBSCRIBER/PUBLISHER: what the API joins to the name it is given
    # (an interactive marker server subscribes <topic_ns>/feedback)
    topic_suffix: str = ''
    # PARAM_READ: (position, keyword) of the default value
    default: Optional[tuple] = None
    # PARAM_READ: ROS 2 parameters always belong to the node itself
    node_private: bool = False
    # PARAM_READ of several parameters: (position, keyword) of the list of
    # (name, default[, descriptor]) tuples, and of the namespace their
    # names are joined to with '.'
    param_list: Optional[tuple] = None
    param_namespace: Optional[tuple] = None
    # PUBLISHER: (position, keyword) of an argument that, when given and
    # not a string, makes the object publish from a timer of its own
    # (ROS 2 diagnostic_updater.Updater(node, period)); `period` gives the
    # timer's period, else `default_period` seconds
    own_timer: Optional[tuple] = None
    default_period: Optional[float] = None
    # PUBLISHER: (position, keyword) of a publisher the object wraps: it
    # makes no publisher of its own, its publish sites are the wrapped
    # one's (diagnostic_updater.DiagnosedPublisher(pub, ...))
    wraps: Optional[tuple] = None


NODE = NODE_CLASS + '.'

CALLS = {
    # --- rospy (ROS 1) ---
    'rospy.init_node': PyApi(NODE_HANDLE),
    'rospy.get_param': PyApi(
        PARAM_READ, name=(0, 'param_name'), default=(1, 'default')),
    'rospy.Publisher': PyApi(
        PUBLISHER, name=(0, 'name'), msg_type_arg=(1, 'data_class')),
    'rospy.Publisher.publish': PyApi(PUBLISH),
    'rospy.Subscriber': PyApi(
        SUBSCRIBER, name=(0, 'name'), msg_type_arg=(1, 'data_class'),
        callback=(2, 'callback'), callback_args=(3, 'callback_args')),
    'rospy.wait_for_message': PyApi(
        SUBSCRIBER, name=(0, 'topic'), msg_type_arg=(1, 'topic_type'),
        returns='rospy.Message'),
    'rospy.Timer': PyApi(
        TIMER, period=(0, 'period'), period_unit=DURATION,
        callback=(1, 'callback')),
    'rospy.Rate': PyApi(RATE, period=(0, 'hz'), period_unit=HZ),
    'rospy.Rate.sleep': PyApi(RATE_SLEEP),
    'rospy.sleep': PyApi(SLEEP),
    'rospy.Service': PyApi(
        SERVICE, name=(0, 'name'), msg_type_arg=(1, 'service_class'),
        callback=(2, 'handler')),
    'rospy.ServiceProxy': PyApi(SERVICE_CLIENT, name=(0, 'name')),
    # --- actionlib (ROS 1) ---
    'actionlib.SimpleActionServer': PyApi(
        ACTION_SERVER, name=(0, 'name'), callback=(2, 'execute_cb')),
    'actionlib.SimpleActionServer.register_goal_callback': PyApi(
        ACTION_SERVER, callback=(0, 'goal_callback')),
    'actionlib.SimpleActionServer.register_preempt_callback': PyApi(
        ACTION_SERVER, callback=(0, 'preempt_callback')),
    'actionlib.ActionServer': PyApi(
        ACTION_SERVER, name=(0, 'ns'), callback=(2, 'goal_cb'),
        extra_callbacks=((3, 'cancel_cb'),)),
    'actionlib.SimpleActionClient': PyApi(ACTION_CLIENT, name=(0, 'ns')),
    'actionlib.ActionClient': PyApi(ACTION_CLIENT, name=(0, 'ns')),
    # --- rclpy (ROS 2) ---
    'rclpy.create_node': PyApi(NODE_HANDLE, returns=NODE_CLASS),
    NODE_CLASS: PyApi(NODE_HANDLE),
    NODE + 'create_publisher': PyApi(
        PUBLISHER, name=(1, 'topic'), msg_type_arg=(0, 'msg_type'),
        returns='rclpy.publisher.Publisher'),
    NODE + 'create_lifecycle_publisher': PyApi(
        PUBLISHER, name=(1, 'topic'), msg_type_arg=(0, 'msg_type'),
        returns='rclpy.publisher.Publisher'),
    'rclpy.publisher.Publisher.publish': PyApi(PUBLISH),
    NODE + 'create_subscription': PyApi(
        SUBSCRIBER, name=(1, 'topic'), msg_type_arg=(0, 'msg_type'),
        callback=(2, 'callback'), returns='rclpy.subscription.Subscription'),
    'rclpy.wait_for_message.wait_for_message': PyApi(
        SUBSCRIBER, name=(2, 'topic'), msg_type_arg=(0, 'msg_type'),
        returns='builtins.tuple'),
    NODE + 'create_timer': PyApi(
        TIMER, period=(0, 'timer_period_sec'), period_unit=SECONDS,
        callback=(1, 'callback'), returns='rclpy.timer.Timer'),
    # parameter reads: a topic name may come from one (the value of
    # declare_parameter/get_parameter is read through .value or
    # .get_parameter_value().string_value)
    NODE + 'declare_parameter': PyApi(
        PARAM_READ, name=(0, 'name'), default=(1, 'value'),
        node_private=True),
    NODE + 'declare_parameters': PyApi(
        PARAM_READ, param_namespace=(0, 'namespace'),
        param_list=(1, 'parameters'), node_private=True),
    NODE + 'get_parameter': PyApi(
        PARAM_READ, name=(0, 'name'), node_private=True),
    NODE + 'create_rate': PyApi(
        RATE, period=(0, 'frequency'), period_unit=HZ,
        returns='rclpy.timer.Rate'),
    'rclpy.timer.Rate.sleep': PyApi(RATE_SLEEP),
    NODE + 'create_service': PyApi(
        SERVICE, name=(1, 'srv_name'), msg_type_arg=(0, 'srv_type'),
        callback=(2, 'callback'), returns='rclpy.service.Service'),
    NODE + 'create_client': PyApi(
        SERVICE_CLIENT, name=(1, 'srv_name'), returns='rclpy.client.Client'),
    'rclpy.action.ActionServer': PyApi(
        ACTION_SERVER, name=(2, 'action_name'),
        callback=(3, 'execute_callback'),
        extra_callbacks=((None, 'goal_callback'),
                         (None, 'handle_accepted_callback'),
                         (None, 'cancel_callback'))),
    'rclpy.action.ActionServer.register_goal_callback': PyApi(
        ACTION_SERVER, callback=(0, 'goal_callback')),
    'rclpy.action.ActionServer.register_cancel_callback': PyApi(
        ACTION_SERVER, callback=(0, 'cancel_callback')),
    'rclpy.action.ActionServer.register_execute_callback': PyApi(
        ACTION_SERVER, callback=(0, 'execute_callback')),
    'rclpy.action.ActionServer.register_handle_accepted_callback': PyApi(
        ACTION_SERVER, callback=(0, 'handle_accepted_callback')),
    'rclpy.action.ActionClient': PyApi(
        ACTION_CLIENT, name=(2, 'action_name')),
    # --- message_filters (ROS 1 and ROS 2) ---
    'message_filters.Subscriber': PyApi(
        SUBSCRIBER, name=(2, 'topic'), msg_type_arg=(1, 'msg_type'),
        ros1_form=((0, 'name'), (1, 'data_class')),
        ros1_keywords=('name', 'data_class'),
        ros2_keywords=('topic', 'msg_type'), ros2_arity=3),
    'message_filters.TimeSynchronizer': PyApi(SYNC, inputs=(0, 'fs')),
    'message_filters.ApproximateTimeSynchronizer': PyApi(
        SYNC, inputs=(0, 'fs')),
    'message_filters.Cache': PyApi(SYNC, inputs=(0, 'f')),
    'message_filters.Subscriber.registerCallback': PyApi(
        REGISTER_CALLBACK, callback=(0, 'cb')),
    'message_filters.TimeSynchronizer.registerCallback': PyApi(
        REGISTER_CALLBACK, callback=(0, 'cb')),
    'message_filters.ApproximateTimeSynchronizer.registerCallback': PyApi(
        REGISTER_CALLBACK, callback=(0, 'cb')),
    'message_filters.Cache.registerCallback': PyApi(
        REGISTER_CALLBACK, callback=(0, 'cb')),
    # --- tf2_ros / tf: broadcasters publish through sendTransform ---
    'tf2_ros.TransformBroadcaster': PyApi(
        PUBLISHER, msg_type=TF_MSG, implicit_topics=('/tf',)),
    'tf2_ros.TransformBroadcaster.sendTransform': PyApi(PUBLISH),
    'tf2_ros.StaticTransformBroadcaster': PyApi(
        PUBLISHER, msg_type=TF_MSG, implicit_topics=('/tf_static',)),
    'tf2_ros.StaticTransformBroadcaster.sendTransform': PyApi(PUBLISH),
    'tf2_ros.TransformListener': PyApi(
        SUBSCRIBER, msg_type=TF_MSG, implicit_topics=('/tf', '/tf_static')),
    'tf.TransformBroadcaster': PyApi(
        PUBLISHER, msg_type=TF_MSG, implicit_topics=('/tf',)),
    'tf.TransformBroadcaster.sendTransform': PyApi(PUBLISH),
    'tf.TransformBroadcaster.sendTransformMessage': PyApi(PUBLISH),
    'tf.TransformListener': PyApi(
        SUBSCRIBER, msg_type=TF_MSG, implicit_topics=('/tf', '/tf_static')),
    # --- interactive_markers: the server subscribes <topic_ns>/feedback
    # (ROS 1 (topic_ns, server_id), ROS 2 (node, topic_ns)) and calls the
    # feedback callbacks given to insert/setCallback (ROS 1 feedback_cb,
    # ROS 2 feedback_callback) and to a MenuHandler's entries from it; its
    # own update publishers are the library's, as actionlib's are ---
    'interactive_markers.InteractiveMarkerServer': PyApi(
        SUBSCRIBER, name=(1, 'topic_ns'), msg_type=MARKER_FEEDBACK_MSG,
        topic_suffix='/feedback', ros1_form=((0, 'topic_ns'), None),
        ros1_keywords=('server_id',), ros2_keywords=('node',),
        ros2_arity=2),
    'interactive_markers.InteractiveMarkerServer.insert': PyApi(
        REGISTER_CALLBACK, callback=(1, 'feedback_cb'),
        extra_callbacks=((None, 'feedback_callback'),)),
    'interactive_markers.InteractiveMarkerServer.setCallback': PyApi(
        REGISTER_CALLBACK, callback=(1, 'feedback_cb'),
        extra_callbacks=((None, 'feedback_callback'),)),
    'interactive_markers.MenuHandler.insert': PyApi(
        REGISTER_CALLBACK, callback=(4, 'callback')),
    # --- diagnostic_updater: the updater publishes /diagnostics ---
    # ROS 1 Updater() publishes when update()/force_update() is called;
    # ROS 2 Updater(node, period=1.0) also from a timer of its own
    'diagnostic_updater.Updater': PyApi(
        PUBLISHER, msg_type=DIAGNOSTICS_MSG,
        implicit_topics=('/diagnostics',), own_timer=(0, 'node'),
        period=(1, 'period'), period_unit=SECONDS, default_period=1.0),
    'diagnostic_updater.Updater.update': PyApi(PUBLISH),
    'diagnostic_updater.Updater.force_update': PyApi(PUBLISH),
    'diagnostic_updater.Updater.broadcast': PyApi(PUBLISH),
    'diagnostic_updater.Updater.publish': PyApi(PUBLISH),
    'diagnostic_updater.DiagnosedPublisher': PyApi(
        PUBLISHER, wraps=(0, 'pub')),
    'diagnostic_updater.DiagnosedPublisher.publish': PyApi(PUBLISH),
    # --- plain sleeps and callback binding ---
    'time.sleep': PyApi(SLEEP),
    'functools.partial': PyApi(PARTIAL),
}

# methods recognised by their name alone when the type of the object they
# are called on is not known (a publisher passed as a parameter, a node
# object handed to a helper class): name -> the API they stand for
DUCK_METHODS = {
    'publish': 'publish',
    'sendTransform': 'sendTransform',
    'registerCallback': 'registerCallback',
    'create_publisher': NODE + 'create_publisher',
    'create_lifecycle_publisher': NODE + 'create_lifecycle_publisher',
    'create_subscription': NODE + 'create_subscription',
    'create_timer': NODE + 'create_timer',
    'create_rate': NODE + 'create_rate',
    'create_service': NODE + 'create_service',
    'create_client': NODE + 'create_client',
}
DUCK_CALLS = {
    'publish': PyApi(PUBLISH),
    'sendTransform': PyApi(PUBLISH),
    'registerCallback': PyApi(REGISTER_CALLBACK, callback=(0, 'cb')),
}

# the libraries the table models, by their top-level modules
API_MODULES = frozenset(
    name.split('.')[0] for name in CALLS) - {'functools', 'time'}

# inner modules the libraries re-export from; a name starting with a key
# (followed by '.' or nothing) is rewritten to start with its value
ALIASES = {
    'rospy.topics.Publisher': 'rospy.Publisher',
    'rospy.topics.Subscriber': 'rospy.Subscriber',
    'rospy.timer.Timer': 'rospy.Timer',
    'rospy.timer.Rate': 'rospy.Rate',
    'rospy.timer.sleep': 'rospy.sleep',
    'rospy.rostime.Duration': 'rospy.Duration',
    'rospy.client.wait_for_message': 'rospy.wait_for_message',
    'rospy.client.init_node': 'rospy.init_node',
    'rospy.impl.tcpros_service.Service': 'rospy.Service',
    'rospy.impl.tcpros_service.ServiceProxy': 'rospy.ServiceProxy',
    'rospy.service.Service': 'rospy.Service',
    'actionlib.simple_action_server.SimpleActionServer':
        'actionlib.SimpleActionServer',
    'actionlib.action_server.ActionServer': 'actionlib.ActionServer',
    'actionlib.simple_action_client.SimpleActionClient':
        'actionlib.SimpleActionClient',
    'actionlib.action_client.ActionClient': 'actionlib.ActionClient',
    # a lifecycle node creates publishers etc. like a node
    'rclpy.lifecycle.node.LifecycleNode': NODE_CLASS,
    'rclpy.lifecycle.LifecycleNode': NODE_CLASS,
    'rclpy.lifecycle.Node': NODE_CLASS,
    'rclpy.action.server.ActionServer': 'rclpy.action.ActionServer',
    'rclpy.action.client.ActionClient': 'rclpy.action.ActionClient',
    'tf2_ros.transform_broadcaster.TransformBroadcaster':
        'tf2_ros.TransformBroadcaster',
    'tf2_ros.static_transform_broadcaster.StaticTransformBroadcaster':
        'tf2_ros.StaticTransformBroadcaster',
    'tf2_ros.transform_listener.TransformListener':
        'tf2_ros.TransformListener',
    'tf.broadcaster.TransformBroadcaster': 'tf.TransformBroadcaster',
    'interactive_markers.interactive_marker_server.InteractiveMarkerServer':
        'interactive_markers.InteractiveMarkerServer',
    'interactive_markers.menu_handler.MenuHandler':
        'interactive_markers.MenuHandler',
    'diagnostic_updater._diagnostic_updater.Updater':
        'diagnostic_updater.Updater',
    'diagnostic_updater._publisher.DiagnosedPublisher':
        'diagnostic_updater.DiagnosedPublisher',
    'tf.listener.TransformListener': 'tf.TransformListener',
}

# Duration constructors: name -> ((keyword, position, seconds per unit), …)
DURATIONS = {
    'rospy.Duration': (('secs', 0, 1.0), ('nsecs', 1, 1e-9)),
    'rospy.Duration.from_sec': (('float_secs', 0, 1.0),),
    'rclpy.duration.Duration': (
        ('seconds', None, 1.0), ('nanoseconds', None, 1e-9)),
}

# rclpy.node.Node methods that are not in CALLS: a call of one of these on
# `self` in a node class is the library's, not a method some subclass of
# the package is expected to define
# the calls that name the node (first argument, or `name`/`node_name`)
NODE_NAMING = frozenset({'rospy.init_node', 'rclpy.create_node', NODE_CLASS})

NODE_METHODS = frozenset({
    'get_logger', 'get_clock', 'get_name', 'get_namespace',
    'get_fully_qualified_name', 'declare_parameter',
    'get_parameter', 'get_parameters', 'get_parameter_or',
    'get_parameters_by_prefix', 'has_parameter', 'set_parameters',
    'set_parameters_atomically', 'undeclare_parameter',
    'add_on_set_parameters_callback', 'remove_on_set_parameters_callback',
    'destroy_node', 'destroy_publisher', 'destroy_subscription',
    'destroy_timer', 'destroy_rate', 'destroy_service', 'destroy_client',
    'create_guard_condition', 'count_publishers', 'count_subscribers',
    'get_topic_names_and_types', 'get_node_names',
    'get_publishers_info_by_topic', 'get_subscriptions_info_by_topic',
    'executor', 'context', 'handle',
})


def canonical(name):
    """Return the canonical dotted name of an external name."""
    if name is None:
        return None
    parts = name.split('.')
    for cut in range(len(parts), 0, -1):
        head = '.'.join(parts[:cut])
        target = ALIASES.get(head)
        if target is not None:
            return '.'.join([target] + parts[cut:])
    return name


def lookup(name):
    """Return the :class:`PyApi` of a canonical name, or None."""
    return CALLS.get(name)
