# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What each recognised Python API does to the facts.

Part of the Python front end (see :mod:`colcon_rsia.frontend.python`):
mixed into the walk (:mod:`colcon_rsia.frontend.python.walk`), which
answers where names and values lead; the loop context and the pacing rule
are the recorder's (:mod:`colcon_rsia.frontend.recorder`).
"""

import ast

from colcon_rsia.frontend import fact_builder
from colcon_rsia.frontend import python_api
from colcon_rsia.frontend import recorder
from colcon_rsia.frontend.python.scopes import region
from colcon_rsia.frontend.python.scopes import SCOPE_NODES
from colcon_rsia.frontend.python.values import call_argument

LOOP_NODES = (ast.For, ast.AsyncFor, ast.While)


class Roles:
    """The handlers of the python_api roles, named after them."""

    def _on_node_handle(self, api, name, node, context):
        """The node's name: ``rospy.init_node("n")``, ``Node("n", namespace=)``."""
        if name not in python_api.NODE_NAMING:
            return
        written = call_argument(node, (0, 'name')) or \
            call_argument(node, (0, 'node_name'))
        node_name, literal = self._topic(written, context)
        namespace, ns_literal = self._topic(
            call_argument(node, (None, 'namespace')), context)
        # super().__init__(node_name) in a base class of the package: the
        # name its subclasses pass
        name_param = self.project.handle(written, context.scope) \
            if isinstance(written, ast.Name) else None
        fact_builder.add_node_name(
            self.facts, function=context.function, name=node_name if literal else None,
            namespace=namespace if ns_literal else None,
            location=self.location(node), name_param=name_param)

    def _topics(self, api, node, name_arg, context):
        """([(topic, literal)], the topic's argument) of an endpoint call.

        The API's fixed topics (tf's), else the one its argument names;
        None when that argument is no name (nothing is recorded).
        """
        if api.implicit_topics:
            return [(topic, True) for topic in api.implicit_topics], None
        argument = call_argument(node, name_arg)
        topic, literal = self._topic(argument, context)
        if topic is None:
            return None
        if api.topic_suffix:
            topic = topic + api.topic_suffix if literal \
                else f'{topic} + {api.topic_suffix!r}'
        return [(topic, literal)], argument

    def _topic_source_of(self, api, argument, context):
        """_topic_source of a name argument, with what the API joins."""
        source, affixes = self._topic_source(argument, context)
        if source is not None and api.topic_suffix:
            prefix, suffix = affixes or ('', '')
            affixes = [prefix, suffix + api.topic_suffix]
        return source, affixes

    def _on_publisher(self, api, name, node, context):
        if self._wrapped_publisher(api, node, context):
            return
        msg_type = api.msg_type or self._msg_type(
            call_argument(node, api.msg_type_arg), context)
        found = self._topics(api, node, api.name, context)
        if found is None:
            return
        topics, argument = found
        handle, handle_name = self._target(node, context)
        if api.own_timer is not None and handle is not None and \
                self._given_object(call_argument(node, api.own_timer),
                                   context):
            self._own_timer(api, name, node, context, handle)
        for topic, literal in topics:
            source, affixes = (None, None) if literal else \
                self._topic_source_of(api, argument, context)
            fact_builder.add_publisher(
                self.facts, function=context.function, api=name, topic=topic,
                topic_is_literal=literal, msg_type=msg_type, handle=handle,
                handle_name=handle_name, location=self.location(node),
                topic_handle=source, topic_affixes=affixes)

    def _given_object(self, argument, context):
        """Whether an argument is written and is no string."""
        return argument is not None and \
            self.project.string(argument, context.scope) is None and \
            not isinstance(argument, ast.JoinedStr)

    def _wrapped_publisher(self, api, node, context):
        """``DiagnosedPublisher(pub, ...)`` publishes through `pub`.

        Returns whether the call is such a wrapper (it then makes no
        publisher of its own; its publish sites count for `pub`).
        """
        if api.wraps is None:
            return False
        wrapped = call_argument(node, api.wraps)
        if not self._given_object(wrapped, context):
            return False
        alias, _ = self._target(node, context)
        handle = self._object_handle(wrapped, context)
        if alias is not None and handle is not None:
            fact_builder.add_handle_alias(
                self.facts, alias=alias, handle=handle, location=self.location(node))
        return True

    def _own_timer(self, api, name, node, context, handle):
        """An object publishing from a timer of its own (ROS 2 Updater).

        Recorded as what it does, as in C++: a timer whose callback (a
        function made up for it, at the construction) publishes through
        the object.
        """
        location = self.location(node)
        # what the real timer calls; the id is unique per object
        callback = f'{name}.update@{location}'
        fact_builder.add_function(
            self.facts, id=callback, name=f'{name}.update', location=location)
        period = call_argument(node, api.period)
        rate_hz = self._rate_hz(period, api.period_unit, context) \
            if period is not None \
            else recorder.rate_of_period(api.default_period)
        fact_builder.add_timer(
            self.facts, function=context.function, api=name, callback=callback,
            period=self.text(period) if period is not None
            else str(api.default_period),
            rate_hz=rate_hz, location=location)
        fact_builder.add_publish_site(
            self.facts, function=callback, api=name, handle=handle, location=location)

    def _on_subscriber(self, api, name, node, context):
        name_arg, type_arg = api.name, api.msg_type_arg
        if api.ros1_form is not None and self._ros1_form(api, node, context):
            name_arg, type_arg = api.ros1_form
        msg_type = api.msg_type or self._msg_type(
            call_argument(node, type_arg), context)
        found = self._topics(api, node, name_arg, context)
        if found is None:
            return
        topics, argument = found
        callback, scope, offset = self._callback(
            call_argument(node, api.callback), context)
        callback_args = call_argument(node, api.callback_args)
        if scope is not None and callback_args is not None and \
                len(scope.params) > 1:
            # called as callback(msg, callback_args)
            self._bind_one(scope, 1, callback_args, context)
        handle, _ = self._target(node, context)
        for topic, literal in topics:
            source, affixes = (None, None) if literal else \
                self._topic_source_of(api, argument, context)
            fact_builder.add_subscriber(
                self.facts, function=context.function, api=name, topic=topic,
                topic_is_literal=literal, msg_type=msg_type, handle=handle,
                callback=callback, location=self.location(node),
                topic_handle=source, topic_affixes=affixes)

    def _on_timer(self, api, name, node, context):
        callback, _, _ = self._callback(
            call_argument(node, api.callback), context)
        period = call_argument(node, api.period)
        fact_builder.add_timer(
            self.facts, function=context.function, api=name, callback=callback,
            period=self.text(period) if period is not None else '',
            rate_hz=self._rate_hz(period, api.period_unit, context),
            location=self.location(node))

    def _on_service(self, api, name, node, context):
        service, _ = self._topic(call_argument(node, api.name), context)
        callback, _, _ = self._callback(
            call_argument(node, api.callback), context)
        fact_builder.add_service(
            self.facts, function=context.function, api=name, name=service,
            callback=callback, location=self.location(node))

    def _on_service_client(self, api, name, node, context):
        service, _ = self._topic(call_argument(node, api.name), context)
        fact_builder.add_client(
            self.facts, function=context.function, api=name, name=service,
            location=self.location(node))

    def _on_action_server(self, api, name, node, context):
        self._action(api, name, node, context, 'server')

    def _on_action_client(self, api, name, node, context):
        self._action(api, name, node, context, 'client')

    def _action(self, api, name, node, context, role):
        registration = api.name is None
        action = None
        if not registration:
            action, _ = self._topic(call_argument(node, api.name), context)
        callbacks = []
        specs = ((api.callback,) if api.callback else ()) + \
            api.extra_callbacks
        for spec in specs:
            callback, _, _ = self._callback(call_argument(node, spec), context)
            if callback:
                callbacks.append(callback)
        if registration:
            handle = self._receiver(node, context)
            label = name.rsplit('.', 1)[0]
            location = 'registration:' + self.location(node)
        else:
            handle, _ = self._target(node, context)
            label = name
            location = self.location(node)
        fact_builder.add_action(
            self.facts, function=context.function, api=label, role=role, name=action,
            callbacks=callbacks, handle=handle, location=location)

    def _on_publish(self, api, name, node, context):
        fact_builder.add_publish_site(
            self.facts, function=context.function, api=name,
            handle=self._receiver(node, context),
            location=self.location(node), loops=context.loop_ids())

    def _on_rate(self, api, name, node, context):
        handle, _ = self._target(node, context)
        if handle is None or handle.startswith('new@'):
            return  # a temporary Rate paces nothing
        argument = call_argument(node, api.period)
        fact_builder.add_rate(
            self.facts, handle=handle,
            rate_hz=self._rate_hz(argument, api.period_unit, context),
            expression=self.text(argument) if argument is not None else '',
            location=self.location(node))

    def _on_rate_sleep(self, api, name, node, context):
        handle = self._receiver(node, context)
        if handle is None or handle.startswith('new@'):
            return  # rospy.Rate(10).sleep(): a new Rate never adapts
        paced = recorder.paced_loop(
            context,
            made_in_loop=lambda loop: self._assigned_in(loop, handle, context),
            continue_before=lambda loop: _continue_before(loop, node))
        if paced is None:
            return
        loop_id, loop = paced
        recorder.record_paced_loop(
            self.facts, context, loop_id=loop_id, clock=handle,
            loop_location=self.location(loop),
            sleep_location=self.location(node))

    def _assigned_in(self, loop, handle, context):
        for node in region([loop]):
            targets = []
            if isinstance(node, ast.Assign):
                targets = node.targets
            elif isinstance(node, (ast.AnnAssign, ast.NamedExpr)):
                targets = [node.target]
            elif isinstance(node, ast.withitem) and node.optional_vars:
                targets = [node.optional_vars]
            for target in targets:
                for each in ast.walk(target):
                    if isinstance(each, (ast.Name, ast.Attribute)) and \
                            self.project.handle(each, context.scope) == \
                            handle:
                        return True
        return False

    def _on_sync(self, api, name, node, context):
        inputs = []
        for element in self._elements(call_argument(node, api.inputs), context):
            handle = self._object_handle(element, context)
            if handle is not None:
                inputs.append(handle)
        handle, _ = self._target(node, context)
        fact_builder.add_sync(
            self.facts, handle=handle, inputs=inputs, location=self.location(node))

    def _on_register_callback(self, api, name, node, context):
        specs = (api.callback,) + api.extra_callbacks
        for argument in (call_argument(node, spec) for spec in specs):
            if argument is None:
                continue
            callback, _, _ = self._callback(argument, context)
            fact_builder.add_registration(
                self.facts, function=context.function,
                handle=self._receiver(node, context), callback=callback,
                location=self.location(node))


def _continue_before(loop, sleep):
    """Whether a `continue` of this loop comes before the sleep call."""
    where = (sleep.lineno, sleep.col_offset)
    todo = list(loop.body)
    while todo:
        node = todo.pop()
        if isinstance(node, ast.Continue) and \
                (node.lineno, node.col_offset) < where:
            return True
        if isinstance(node, LOOP_NODES):
            todo.extend(node.orelse)  # the inner loop's continue is its own
            continue
        if isinstance(node, SCOPE_NODES):
            continue
        todo.extend(ast.iter_child_nodes(node))
    return False
