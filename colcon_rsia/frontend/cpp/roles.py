# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What each recognised ROS API does to the facts of a unit.

The walker (:mod:`colcon_rsia.frontend.cpp.walker`) finds a call and its
role in :mod:`colcon_rsia.frontend.ros_api`; the handler of that role here
reads the call's arguments into facts: a publisher, a subscriber, a timer,
a rate, a NodeHandle's namespace, a parameter read... Handlers are named
after the roles (``_on_<role>``) and dispatched through the walker's
explicit table (:meth:`RosRoles.handlers`).
"""

import dataclasses
import re

import clang.cindex as ci
from colcon_rsia.frontend import fact_builder
from colcon_rsia.frontend import recorder
from colcon_rsia.frontend import ros_api
from colcon_rsia.frontend.cpp import hosted
from colcon_rsia.frontend.cpp.callbacks import CALLABLE_PREFIX
from colcon_rsia.frontend.cpp.const_eval import evaluate_number
from colcon_rsia.frontend.cpp.const_eval import evaluate_period_seconds
from colcon_rsia.frontend.cpp.const_eval import is_chrono_duration
from colcon_rsia.frontend.cpp.cursors import call_object
from colcon_rsia.frontend.cpp.cursors import callback_msg_type
from colcon_rsia.frontend.cpp.cursors import child_cursors
from colcon_rsia.frontend.cpp.cursors import explicit_template_type
from colcon_rsia.frontend.cpp.cursors import expression_text
from colcon_rsia.frontend.cpp.cursors import first_handle
from colcon_rsia.frontend.cpp.cursors import first_template_argument
from colcon_rsia.frontend.cpp.cursors import handle_marker
from colcon_rsia.frontend.cpp.cursors import initializer
from colcon_rsia.frontend.cpp.cursors import is_callable_argument
from colcon_rsia.frontend.cpp.cursors import is_node_handle
from colcon_rsia.frontend.cpp.cursors import is_string
from colcon_rsia.frontend.cpp.cursors import normalize_msg_type
from colcon_rsia.frontend.cpp.cursors import qualified_name
from colcon_rsia.frontend.cpp.cursors import ranged_container
from colcon_rsia.frontend.cpp.cursors import role_argument
from colcon_rsia.frontend.cpp.cursors import same_cursor
from colcon_rsia.frontend.cpp.cursors import template_member
from colcon_rsia.frontend.cpp.cursors import walk_preorder
from colcon_rsia.frontend.cpp.cursors import written_arguments
from colcon_rsia.frontend.cpp.questions import paced_loop
from colcon_rsia.frontend.cpp.questions import record_paced_loop
from colcon_rsia.frontend.cpp.questions import record_publish_site
from colcon_rsia.frontend.cpp.questions import stored_target
from colcon_rsia.frontend.cpp.strings import string_parts
from colcon_rsia.frontend.cpp.strings import topic_source
from colcon_rsia.frontend.cpp.strings import written_name
from colcon_rsia.summary.kinds import UNKNOWN_NAMESPACE

CK = ci.CursorKind

_SMART_POINTER = re.compile(r'^(?:std|boost)::(?:shared_ptr|unique_ptr)<')

# the option objects roscpp's subscribe/advertise also take
_OPTIONS_TYPES = frozenset({'ros::SubscribeOptions', 'ros::AdvertiseOptions'})


class RosRoles:
    """The handlers of the ROS API roles, for one walk."""

    def __init__(  # noqa: D107
            self, facts, places, *, resolve_callback, string_variables,
            stored_then_registered):
        # the unit's facts: one object for the whole walk
        self.facts = facts
        # where cursors are (questions.Places)
        self.places = places
        # (function id, declaration) of a callback argument (callbacks.py)
        self.resolve_callback = resolve_callback
        # what string variables hold (strings.StringVariables)
        self.string_variables = string_variables
        # callbacks an options object held before it was registered
        self.stored_then_registered = stored_then_registered

    def handlers(self):
        """The walker's handlers for the roles of ros_api."""
        return {
            ros_api.PUBLISHER: self._on_publisher,
            ros_api.SUBSCRIBER: self._on_subscriber,
            ros_api.TIMER: self._on_timer,
            ros_api.SERVICE: self._on_service,
            ros_api.CLIENT: self._on_client,
            ros_api.PUBLISH: self._on_publish,
            ros_api.RATE: self._on_rate,
            ros_api.RATE_SLEEP: self._on_rate_sleep,
            ros_api.SYNC: self._on_sync,
            ros_api.REGISTER_CALLBACK: self._on_register_callback,
            ros_api.ACTION_SERVER: self._on_action_server,
            ros_api.ACTION_CLIENT: self._on_action_client,
            ros_api.NODE_HANDLE: self._on_node_handle,
            ros_api.PRIVATE_HANDLE: self._on_private_handle,
            ros_api.PUBLIC_HANDLE: self._on_public_handle,
            ros_api.PARAM_READ: self._on_param_read,
            ros_api.NODE_NAME: self._on_node_name,
            ros_api.SUB_NODE: self._on_sub_node,
            ros_api.TIMED_PUBLISHER: self._on_timed_publisher,
            # the value is read where it is stored (strings.py)
            ros_api.NAME_RESOLVE: self._on_name_resolve,
            ros_api.NODE_FQN: self._on_name_resolve,
            # gzserver's events, nodelets loaded in code
            **hosted.HostedRoles(
                self.facts, self.places,
                resolve_callback=self.resolve_callback).handlers(),
        }

    def _callbacks(self, arguments, position):
        if position == ros_api.ALL_CALLABLES:
            candidates = [a for a in arguments if is_callable_argument(a)]
        elif position == ros_api.FIRST_CALLBACK:
            candidates = arguments
        else:
            positions = position if isinstance(position, tuple) \
                else (position,)
            candidates = [role_argument(arguments, p) for p in positions]
        found = []
        for argument in candidates:
            callback, _ = self.resolve_callback(argument)
            if callback:
                found.append(callback)
        return found

    def _namespace_of(self, call, api=None, arguments=()):
        """The NodeHandle a create call was made on: USR or marker.

        For an API that takes the NodeHandle as an argument
        (``message_filters::Subscriber(nh, topic, 1)``), that argument.
        """
        obj = call_object(call) or _wrapped_call_object(call)
        if api is not None and api.nh_arg is not None and \
                api.nh_arg < len(arguments):
            obj = arguments[api.nh_arg]
        return handle_marker(obj, self._foreign_handle,
                             self.places.in_package)

    def _foreign_handle(self, member):
        """A ROS 1 NodeHandle member of a class of another library.

        (``pnh_`` of a nodelet base class the package derives from): its
        namespace is whatever that library's code gives it.
        """
        return not self.places.ros2 and not self.places.in_package(member)

    # --- roles (named after ros_api roles) ----------------------------------

    def _on_publisher(self, cursor, ctx, stack, api, name, arguments):
        if self._wrapped_publisher(cursor, stack, api, arguments):
            return
        # ROS 2: an options object passed along, whose matched callback
        # (stored with it by the walker) runs as a connect callback
        options_callbacks = [
            CALLABLE_PREFIX + holder.get_usr() for holder in map(
                first_handle, arguments)
            if holder is not None] if self.places.ros2 else []
        typed, api, arguments = self._with_options(cursor, api, arguments)
        topic, literal = written_name(role_argument(arguments, api.name_arg))
        if topic is None and name.endswith('::init'):
            return
        if topic is None and api.name_arg and len(arguments) <= api.name_arg:
            return  # a default constructor: the topic comes with init()
        msg_type = self.places.table_msg_type(api.msg_type) or \
            self._type_name(arguments, api) or \
            self._template_msg_type(typed, name)
        target = stored_target(cursor, stack)
        status_callbacks = [
            callback for position in api.status_callback_args
            for callback in [self.resolve_callback(
                role_argument(arguments, position))[0]] if callback] + \
            options_callbacks
        for common in self._endpoints(cursor, ctx, api, name, arguments,
                                      topic, literal, msg_type, target):
            fact_builder.add_publisher(
                self.facts, handle_name=target.spelling if target is not None else None,
                status_callbacks=status_callbacks, **common)
        self.string_variables.concatenation(
            self.facts.publishers[-1:], literal,
            role_argument(arguments, api.name_arg))

    def _wrapped_publisher(self, cursor, stack, api, arguments):
        """``RealtimePublisher<M>(pub)`` publishes through `pub`.

        Returns whether the call is such a wrapper (then it makes no
        publisher of its own; its publish sites count for `pub`).
        """
        if api.wraps_arg is None:
            return False
        written = written_arguments(arguments)
        wrapped = role_argument(arguments, api.wraps_arg)
        if len(written) != 1 or wrapped is None or is_string(wrapped):
            return False
        target = stored_target(cursor, stack)
        handle = first_handle(wrapped)
        if target is not None and handle is not None:
            fact_builder.add_handle_alias(
                self.facts, alias=target.get_usr(), handle=handle.get_usr(),
                location=self.places.location(cursor))
        return True

    def _argument_msg_type(self, arguments, api):
        if api.msg_type_arg is None:
            return None
        argument = role_argument(arguments, api.msg_type_arg)
        return normalize_msg_type(argument.type.get_canonical().spelling) \
            if argument is not None else None

    def _type_name(self, arguments, api):
        """The message type a generic API names: "pkg/msg/Name"."""
        if api.type_name_arg is None:
            return None
        written, literal = written_name(
            role_argument(arguments, api.type_name_arg))
        if not literal or not re.fullmatch(r'\w+/\w+/\w+', written or ''):
            return None
        return written.replace('/', '::')

    def _template_msg_type(self, cursor, name):
        """The message type from ``<M>`` at the call or in the class."""
        return normalize_msg_type(
            explicit_template_type(cursor) or
            first_template_argument(self._object_type(cursor, name)))

    def _endpoints(self, cursor, ctx, api, name, arguments, topic, literal,
                   msg_type, target):
        """The fields shared by publisher and subscriber facts, per topic.

        image_transport's camera APIs also make `<dirname>/camera_info`.
        A name resolved in place (``advertise(nh.resolveName("out"), 1)``)
        is that name in the resolving handle's namespace.
        """
        nh = self._namespace_of(cursor, api, arguments)
        resolved = None if literal or api.name_arg is None else \
            self.string_variables.resolved_in_place(
                role_argument(arguments, api.name_arg))
        if resolved is not None:
            topic, literal, nh = resolved[0], True, resolved[1]
        topics = [(topic, msg_type)]
        if api.camera:
            topics.append((_camera_info(topic),
                           self.places.table_msg_type(ros_api.CAMERA_INFO_MSG)))
        topic_handle, affixes = self._topic_handle(arguments, api, literal)
        # (a camera's second topic is made of the first: not a parameter)
        from_argument = None if api.camera else _parameter_index(
            role_argument(arguments, api.name_arg), topic_handle, ctx)
        for each_topic, each_type in topics:
            yield dict(
                topic_handle=topic_handle, topic_affixes=affixes,
                topic_argument=from_argument,
                function=ctx.function, api=ros_api.api_label(name),
                topic=each_topic, topic_is_literal=literal,
                msg_type=each_type,
                handle=target.get_usr() if target is not None else None,
                location=self.places.location(cursor), nh=nh)

    def _object_type(self, cursor, name):
        """The class type a constructor or method belongs to.

        Canonical, so that aliases (``using Image = ...``) name the real
        message; through a smart pointer, the class pointed to.
        """
        if name.split('::')[-1] == name.split('::')[-2]:
            type_ = cursor.type
        else:
            obj = call_object(cursor)
            if obj is None:
                return ''
            type_ = obj.type
        spelling = type_.get_canonical().spelling
        if _SMART_POINTER.match(spelling):
            spelling = first_template_argument(spelling) or spelling
        return spelling

    def _options_call(self, argument):
        """The call that filled a ros::*Options object.

        ``nh.subscribe(ops)`` / ``nh.advertise(ops)`` take the topic, the
        message type and the callback from ``ops =
        ros::SubscribeOptions::create<M>(topic, queue, callback, ...)`` or
        from ``ops.init<M>(topic, queue, callback)`` in the same function,
        or the topic from the constructor that took it first (``ros::
        AdvertiseOptions ops(topic, queue, md5sum, datatype, definition)``).
        """
        if argument is None:
            return None
        options = re.sub(r'^const |\s*&$', '',
                         argument.type.get_canonical().spelling)
        if options not in _OPTIONS_TYPES:
            return None
        handle = first_handle(argument)
        if handle is None:
            return None
        fillers = {f'{options}::create', f'{options}::init',
                   f"{options}::{options.rsplit('::', 1)[-1]}"}
        found = None
        scopes = [handle] + ([handle.semantic_parent]
                             if handle.kind == CK.VAR_DECL else [])
        for scope in scopes:
            for node in walk_preorder(scope):
                if node.kind != CK.CALL_EXPR or node.referenced is None or \
                        qualified_name(node.referenced) not in fillers:
                    continue
                if node.referenced.kind == CK.CONSTRUCTOR and \
                        len(list(node.get_arguments())) < 2:
                    continue  # a default or copy construction: no topic
                if scope is handle or same_cursor(
                        first_handle(call_object(node)), handle):
                    found = node  # the last one written wins
            if found is not None:
                return found
        return None

    def _with_options(self, cursor, api, arguments):
        """(call with the endpoint's arguments, api, arguments)."""
        options = self._options_call(role_argument(arguments, api.name_arg))
        if options is None:
            return cursor, api, arguments
        # create/init(topic, queue_size, callback, ...): a subscription's
        # callback is the third argument, an advertisement has none; the
        # constructors take none (their third argument is the checksum)
        takes_callback = api.callback_arg is not None and \
            options.referenced.kind != CK.CONSTRUCTOR
        return options, dataclasses.replace(
            api, name_arg=0, callback_arg=2 if takes_callback else None), \
            list(options.get_arguments())

    def _on_subscriber(self, cursor, ctx, stack, api, name, arguments):
        typed, api, arguments = self._with_options(cursor, api, arguments)
        topic, literal = written_name(role_argument(arguments, api.name_arg))
        if api.name_arg is None and len(api.implicit_topics) == 1:
            # a subscription to the one topic the API names
            # (on_parameter_event: /parameter_events)
            topic, literal = api.implicit_topics[0], True
        if topic is None:
            return  # a default-constructed message_filters::Subscriber
        callback, declaration = self.resolve_callback(
            role_argument(arguments, api.callback_arg)) \
            if api.callback_arg is not None else (None, None)
        if api.type_name_arg is not None:
            # generic: the callback takes serialized messages of any type
            msg_type = self._type_name(arguments, api)
        else:
            msg_type = self.places.table_msg_type(api.msg_type) or \
                self._template_msg_type(typed, name) or \
                self._argument_msg_type(arguments, api) or \
                callback_msg_type(declaration)
        target = stored_target(cursor, stack)
        if target is None and api.callback_arg is None:
            target = first_handle(call_object(cursor))
        for common in self._endpoints(cursor, ctx, api, name, arguments,
                                      topic, literal, msg_type, target):
            fact_builder.add_subscriber(
                self.facts, callback=callback, **common)
        self.string_variables.concatenation(
            self.facts.subscribers[-1:], literal,
            role_argument(arguments, api.name_arg))

    def _topic_handle(self, arguments, api, literal):
        """(handle, affixes): where a non-literal topic comes from."""
        if literal:
            return None, None
        return topic_source(role_argument(arguments, api.name_arg))

    def _on_param_read(self, cursor, ctx, stack, api, name, arguments):
        param, literal = written_name(role_argument(arguments, 0))
        if not literal:
            return
        written = written_arguments(arguments)
        if api.returns_value or len(written) == 1 or (
                name.endswith('::param') and len(written) == 2):
            # value = nh.param("name", default);
            # value = node->declare_parameter("name", default);
            # value = node->get_parameter("name").as_string()
            target = stored_target(cursor, stack)
            default_argument = written[1] if len(written) > 1 else None
        else:
            # nh.param("name", variable, default) / getParam("name", var)
            target = first_handle(written[1]) if len(written) > 1 else None
            default_argument = written[2] if len(written) > 2 else None
        default = None
        if default_argument is not None:
            default, is_literal = written_name(default_argument)
            default = default if is_literal else None
        read = fact_builder.add_param_read(
            self.facts, function=ctx.function, name=param, default=default,
            handle=target.get_usr() if target is not None else None,
            nh='~' if api.node_private else self._namespace_of(cursor),
            location=self.places.location(cursor))
        parts = string_parts(default_argument) \
            if default_argument is not None and default is None else None
        if parts and len(parts) == 1 and parts[0][0] == 'variable':
            self.string_variables.default_from(read, parts[0][1])

    def _on_name_resolve(self, cursor, ctx, stack, api, name, arguments):
        """``nh.resolveName("out")``: a value, read where it is used.

        The call makes no fact; the string variable set to it takes the
        name in the namespace of the handle (StringVariables.assignment).
        So does ``ros::this_node::getName()``: the name ``~`` (strings.written_name,
        strings.string_parts).
        """

    def _on_node_name(self, cursor, ctx, stack, api, name, arguments):
        node_name, literal = written_name(
            role_argument(arguments, api.name_arg))
        namespace = None
        argument = role_argument(arguments, api.namespace_arg) \
            if api.namespace_arg is not None else None
        # Node("name", options) has no namespace argument
        if argument is not None and is_string(argument):
            namespace, ns_literal = written_name(argument)
            namespace = namespace if ns_literal else None
        name_param = None
        if not literal:
            # Base(const std::string & name) : Node(name): the name the
            # callers of Base pass
            handle = first_handle(role_argument(arguments, api.name_arg))
            if handle is not None and handle.kind == CK.PARM_DECL:
                name_param = handle.get_usr()
        fact_builder.add_node_name(
            self.facts, function=ctx.function, name=node_name if literal else None,
            namespace=namespace, location=self.places.location(cursor),
            name_param=name_param)

    def _on_timed_publisher(self, cursor, ctx, stack, api, name, arguments):
        """An object publishing from a timer of its own (ROS 2 Updater).

        Recorded as what it does: a timer whose callback (a function made
        up for it, at the construction) publishes through the object.
        """
        if not self.places.ros2:
            return  # the ROS 1 Updater publishes only when told to
        target = stored_target(cursor, stack)
        if target is None:
            return
        location = self.places.location(cursor)
        # what the real timer calls; the id is unique per object
        callback = f'{api.label}::update@{location}'
        fact_builder.add_function(
            self.facts, id=callback, name=f'{api.label}::update', location=location)
        period = role_argument(arguments, api.period_arg)
        seconds = evaluate_number(period) if period is not None \
            else api.default_period
        rate_hz = recorder.rate_of_period(seconds)
        fact_builder.add_timer(
            self.facts, function=ctx.function, api=api.label, callback=callback,
            period=expression_text(period) if period is not None
            else str(api.default_period),
            rate_hz=rate_hz, location=location)
        fact_builder.add_publish_site(
            self.facts, function=callback, api=api.label, handle=target.get_usr(),
            location=location)

    def _on_client(self, cursor, ctx, stack, api, name, arguments):
        service, _ = written_name(role_argument(arguments, api.name_arg))
        fact_builder.add_client(
            self.facts, function=ctx.function, api=name, name=service,
            location=self.places.location(cursor))

    def _on_timer(self, cursor, ctx, stack, api, name, arguments):
        made = self._timer_options(arguments)
        if made is not None:
            # createTimer(ops): the period and the callback of the
            # TimerOptions(period, callback, queue, ...) it was made with
            api = dataclasses.replace(api, period_arg=0, callback_arg=1)
            arguments = made
        callback, _ = self.resolve_callback(
            role_argument(arguments, api.callback_arg))
        if made is not None and callback:
            self.stored_then_registered.add(callback)
        period = role_argument(arguments, api.period_arg)
        fact_builder.add_timer(
            self.facts, function=ctx.function, api=ros_api.api_label(name),
            callback=callback,
            period=expression_text(period) if period is not None else '',
            rate_hz=_period_rate_hz(period),
            location=self.places.location(cursor))

    def _timer_options(self, arguments):
        """The arguments a timer's options object was constructed with."""
        written = written_arguments(arguments)
        if len(written) != 1 or not re.search(
                r'\bros::(?:Wall|Steady)?TimerOptions\b',
                written[0].type.get_canonical().spelling):
            return None
        handle = first_handle(written[0])
        made = initializer(handle) if handle is not None and \
            handle.kind == CK.VAR_DECL else None
        for current in ([made] + list(walk_preorder(made))) if made else ():
            if current.kind == CK.CALL_EXPR and \
                    len(list(current.get_arguments())) >= 2:
                return list(current.get_arguments())
        return None

    def _on_service(self, cursor, ctx, stack, api, name, arguments):
        argument = role_argument(arguments, api.name_arg)
        service, literal = written_name(argument)
        callback, _ = self.resolve_callback(
            role_argument(arguments, api.callback_arg))
        fact = fact_builder.add_service(
            self.facts, function=ctx.function, api=name, name=service,
            callback=callback, location=self.places.location(cursor))
        handle = first_handle(argument) if not literal else None
        if handle is not None:
            self.string_variables.name_from(fact, handle.get_usr())

    def _on_action_server(self, cursor, ctx, stack, api, name, arguments):
        self._action(cursor, ctx, stack, api, name, arguments, 'server')

    def _on_action_client(self, cursor, ctx, stack, api, name, arguments):
        self._action(cursor, ctx, stack, api, name, arguments, 'client')

    def _action(self, cursor, ctx, stack, api, name, arguments, role):
        action, literal = written_name(
            role_argument(arguments, api.name_arg)) \
            if api.name_arg is not None else (None, False)
        callbacks = self._callbacks(arguments, api.callback_arg) \
            if api.callback_arg is not None else []
        is_registration = api.name_arg is None
        target = first_handle(call_object(cursor)) if is_registration \
            else stored_target(cursor, stack)
        fact_builder.add_action(
            self.facts, function=ctx.function, api=ros_api.api_label(name), role=role,
            name=action, callbacks=callbacks,
            handle=target.get_usr() if target is not None else None,
            location=self.places.location(cursor) if not is_registration
            else 'registration:' + self.places.location(cursor))
        if action is not None and api.action_inputs:
            self._action_inputs(cursor, ctx, api, name, arguments, action,
                                literal, callbacks, target)

    def _action_inputs(self, cursor, ctx, api, name, arguments, action,
                       literal, callbacks, target):
        """The topics a ROS 1 action server subscribes to: `<name>/goal`.

        Relative to the NodeHandle given first, else to the node's
        namespace; the goal message is `<Action>Goal` of the server's
        action type. The callback given runs per goal: a publish there
        follows the goal topic.
        """
        first = arguments[0] if arguments else None
        handle_given = first is not None and is_node_handle(first)
        nh = self._namespace_of(cursor, dataclasses.replace(api, nh_arg=0),
                                arguments) if handle_given else ''
        action_type = first_template_argument(self._object_type(
            cursor, name)) or ''
        action_type = re.sub(r'_<.*', '', action_type)
        # a name held in a variable (a parameter, what the callers pass):
        # the inputs are that name joined with their own
        handle, affixes = self._topic_handle(arguments, api, literal)
        prefix, rest = affixes or ('', '')
        for suffix in api.action_inputs:
            msg_type = f'{action_type}{suffix.capitalize()}' \
                if action_type.endswith('Action') and suffix == 'goal' \
                else 'actionlib_msgs::GoalID' if suffix == 'cancel' else None
            fact_builder.add_subscriber(
                self.facts, function=ctx.function, api=ros_api.api_label(name),
                topic=f'{action}/{suffix}', topic_is_literal=literal,
                msg_type=msg_type,
                handle=target.get_usr() if target is not None else None,
                # (cancel runs the preempt callback, registered apart)
                callback=callbacks[0] if callbacks and suffix == 'goal'
                else None,
                location=self.places.location(cursor), nh=nh,
                topic_handle=handle,
                topic_affixes=[prefix, f'{rest}/{suffix}'] if handle
                else None)

    def _on_publish(self, cursor, ctx, stack, api, name, arguments):
        handle = first_handle(call_object(cursor))
        handle = ranged_container(handle, stack) or handle
        record_publish_site(
            self.facts, self.places.location, ctx, stack, cursor, name,
            handle.get_usr() if handle is not None else None)

    def _on_rate(self, cursor, ctx, stack, api, name, arguments):
        target = stored_target(cursor, stack)
        if target is None:
            return  # a temporary Rate paces nothing
        argument = role_argument(arguments, api.period_arg)
        rate_hz = None
        if argument is not None:
            if is_chrono_duration(argument.type):
                rate_hz = _period_rate_hz(argument)
            elif 'Duration' in argument.type.spelling:
                rate_hz = _period_rate_hz(argument)
            else:
                rate_hz = evaluate_number(argument)
        fact_builder.add_rate(
            self.facts, handle=target.get_usr(), rate_hz=rate_hz,
            expression=expression_text(argument) if argument else '',
            location=self.places.location(cursor))

    def _on_rate_sleep(self, cursor, ctx, stack, api, name, arguments):
        handle = first_handle(call_object(cursor))
        paced = paced_loop(ctx, cursor, handle)
        if paced is None:
            return
        loop_id, loop = paced
        record_paced_loop(
            self.facts, self.places.location, ctx, loop_id=loop_id,
            loop=loop, clock=handle, sleep=cursor)

    def _on_sync(self, cursor, ctx, stack, api, name, arguments):
        if api.input_filter_arg is not None:
            # an input where the target frame follows it: (input, tf,
            # frame, ...), not (tf, frame, ...)
            written = written_arguments(arguments)
            after = api.input_filter_arg + 1
            arguments = [written[api.input_filter_arg]] \
                if len(written) > after and not is_string(written[after]) \
                else []
        inputs = []
        for argument in arguments:
            handle = first_handle(argument)
            if handle is not None:
                inputs.append(handle.get_usr())
        if name.endswith('::connectInput'):
            target = first_handle(call_object(cursor))
        else:
            target = stored_target(cursor, stack)
        fact_builder.add_sync(
            self.facts, handle=target.get_usr() if target is not None else None,
            inputs=inputs, location=self.places.location(cursor))

    def _on_register_callback(self, cursor, ctx, stack, api, name,
                              arguments):
        callback, _ = self.resolve_callback(
            role_argument(arguments, api.callback_arg))
        handle = first_handle(call_object(cursor))
        fact_builder.add_registration(
            self.facts, function=ctx.function,
            handle=handle.get_usr() if handle is not None else None,
            callback=callback, location=self.places.location(cursor))

    def _on_node_handle(self, cursor, ctx, stack, api, name, arguments):
        target = stored_target(cursor, stack)
        if target is None:
            return
        namespace = ''
        written = written_arguments(arguments)
        named = written and is_string(written[0])
        parent = first_handle(written[0]) if written and not named else None
        if parent is not None:
            namespace = 'ref:' + parent.get_usr()
            if len(written) > 1:
                # NodeHandle(parent, "arm"); a sub-namespace not known
                # is marked so
                sub, literal = written_name(written[1])
                namespace += '|' + (
                    sub if literal else UNKNOWN_NAMESPACE + (sub or '?'))
        elif named:
            # ros::NodeHandle nh("arm") / nh(real_name): a string variable
            # set once is its literal (see StringVariables.resolve); a name
            # not known is marked so, never taken for the node's namespace
            namespace, literal = written_name(written[0])
            if not literal:
                variable = first_handle(written[0])
                namespace = UNKNOWN_NAMESPACE + (namespace or '?')
                if variable is not None:
                    fact = fact_builder.add_node_handle(
                        self.facts, handle=target.get_usr(),
                        namespace=namespace)
                    self.string_variables.namespace_from(
                        fact, variable.get_usr())
                    return
        # (ImageTransport(shared_from_this()): a node, not a namespace)
        fact_builder.add_node_handle(
            self.facts, handle=target.get_usr(), namespace=namespace or '')

    def _on_sub_node(self, cursor, ctx, stack, api, name, arguments):
        """``node->create_sub_node("arm")``: a handle in a sub-namespace."""
        target = stored_target(cursor, stack)
        sub, literal = written_name(role_argument(arguments, api.name_arg))
        if target is None or not literal:
            return
        parent = self._namespace_of(cursor)
        fact_builder.add_node_handle(
            self.facts, handle=target.get_usr(),
            namespace=f'ref:{parent}|{sub}' if parent else sub)

    def _on_private_handle(self, cursor, ctx, stack, api, name, arguments):
        target = stored_target(cursor, stack)
        if target is not None:
            fact_builder.add_node_handle(
                self.facts, handle=target.get_usr(), namespace='~')

    def _on_public_handle(self, cursor, ctx, stack, api, name, arguments):
        target = stored_target(cursor, stack)
        if target is not None:
            fact_builder.add_node_handle(
                self.facts, handle=target.get_usr(), namespace='')


def _wrapped_call_object(call):
    """The object of a member call whose callee clang wrapped.

    ``pnh_->advertise<M>(...)`` on what the model mode's repairs declared
    (a name no header of the unit declares): the member reference sits
    under a conversion.
    """
    children = child_cursors(call)
    callee = children[0] if children else None
    if callee is None or callee.kind != CK.UNEXPOSED_EXPR:
        return None
    inner = child_cursors(callee)
    if len(inner) != 1 or inner[0].kind != CK.MEMBER_REF_EXPR:
        return None
    return next((c for c in child_cursors(inner[0]) if c.kind not in (
        CK.TYPE_REF, CK.NAMESPACE_REF, CK.TEMPLATE_REF)), None)


def _camera_info(topic):
    if topic is None:
        return None
    head, _, _ = topic.rpartition('/')
    return f'{head}/camera_info' if head else 'camera_info'


_RATE_CLASSES = ('Rate', 'WallRate')


def _period_rate_hz(argument):
    """Hz of a period argument (``ros::Duration(0.1)``, ``Rate(10)``, 5.0)."""
    if argument is None:
        return None
    seconds = evaluate_period_seconds(argument)
    if seconds:
        return recorder.rate_of_period(seconds)
    # a Rate given where a period goes: its Hz
    for current in [argument] + list(walk_preorder(argument)):
        if current.kind != CK.CALL_EXPR or current.referenced is None or \
                current.referenced.kind != CK.CONSTRUCTOR or \
                current.referenced.spelling not in _RATE_CLASSES:
            continue
        values = [evaluate_number(a) for a in current.get_arguments()]
        if len(values) == 1:
            return recorder.round_rate(values[0]) if values[0] else None
    return None


def _parameter_index(argument, topic_handle, ctx):
    """The index of the walked function's parameter a topic is, or None.

    ``advertise(nh, topic)`` inside ``ShapeShifter::advertise(nh, topic,
    …)``: each call of the function makes an endpoint of what it passes
    (package/node_facts.py).
    """
    handle = first_handle(argument) if argument is not None else None
    if handle is None or handle.kind != CK.PARM_DECL or \
            handle.get_usr() != topic_handle:
        return None
    function = handle.semantic_parent
    if function is None or ctx.function not in (
            function.get_usr(), template_member(function).get_usr()):
        return None
    params = [c for c in function.get_children() if c.kind == CK.PARM_DECL]
    for index, param in enumerate(params):
        if param.get_usr() == topic_handle:
            return index
    return None
