# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Parameter reads, and the topic names that come from them.

Part of the Python front end (see :mod:`colcon_rsia.frontend.python`):
mixed into the walk (:mod:`colcon_rsia.frontend.python.walk`).

A topic whose name is not known may take the value of a parameter:
``rospy.get_param('~topic', 'chatter')``,
``self.declare_parameter('topic', 'scan').value``,
``self.get_parameter('topic').get_parameter_value().string_value``, a
name assigned once from one of them, or a string built around one of
them from known values (``ns + '/cmd_vel'``, ``f'{ns}/odom'``,
``'%s/scan' % ns``, ``'{}/map'.format(ns)``): the endpoint records the
read (its ``topic_handle``) and what is joined around its value (its
``topic_affixes``), and the system graph takes the value the launch
file gives the parameter, else its default.
"""

import ast

from colcon_rsia.frontend import fact_builder
from colcon_rsia.frontend import python_api
from colcon_rsia.frontend import ros_api
from colcon_rsia.frontend.python.values import call_argument
from colcon_rsia.frontend.python.values import EXT
from colcon_rsia.frontend.python.values import EXTBOUND
from colcon_rsia.frontend.python.values import MAX_DEPTH

# stands for a parameter's value while the text around it is computed: a
# character no ROS name may hold
VALUE_MARK = '\0'


class Params:
    """Parameter reads and the names taken from them."""

    def _topic_source(self, expr, context):
        """(parameter read handle, [prefix, suffix]) of a topic not known.

        (None, None) when the topic does not come from one parameter.
        """
        read = self._param_read_of(expr, context.scope, 0)
        if read is not None:
            return self._param_handle(*read), None
        reads = []

        def mark(inner, scope):
            found = self._param_read_of(inner, scope, 0)
            if found is None:
                return None
            reads.append(self._param_handle(*found))
            return VALUE_MARK

        with self.project.substituting(mark):
            text = self.project.string(expr, context.scope)
        if text is None or text.count(VALUE_MARK) != 1 or \
                len(set(reads)) != 1:
            return None, None
        prefix, suffix = text.split(VALUE_MARK)
        return reads[0], [prefix, suffix]

    def _param_read_of(self, expr, scope, depth):
        """(call, scope) of the parameter read `expr` takes its value from.

        ``rospy.get_param('~topic', 'chatter')``,
        ``self.declare_parameter('topic', 'scan').value``,
        ``self.get_parameter('topic').get_parameter_value().string_value``,
        or a name assigned once from one of them.
        """
        if expr is None or depth > MAX_DEPTH:
            return None
        if isinstance(expr, ast.Call):
            return (expr, scope) if self._param_api(expr, scope) else None
        if isinstance(expr, ast.Attribute) and \
                expr.attr in ('value', 'string_value'):
            inner = expr.value
            if expr.attr == 'string_value' and \
                    isinstance(inner, ast.Call) and not inner.args and \
                    isinstance(inner.func, ast.Attribute) and \
                    inner.func.attr == 'get_parameter_value':
                inner = inner.func.value
            read = self._param_read_of(inner, scope, depth + 1)
            if read is not None:
                return read
        source = self.project.sole_source(expr, scope, depth)
        return self._param_read_of(source[0], source[1], depth + 1) \
            if source is not None else None

    def _param_api(self, call, scope):
        called = self.project.value(call.func, scope)
        if called is None or called.kind not in (EXT, EXTBOUND):
            return None
        api = python_api.lookup(called.ref)
        return api if api is not None and \
            api.role == ros_api.PARAM_READ else None

    def _param_handle(self, call, scope):
        # the same for the read and for the topics taking its value
        return f'param@{scope.module.relpath}:{call.lineno}:' \
            f'{call.col_offset}'

    def _on_param_read(self, api, name, node, context):
        if api.param_list is not None:
            self._param_list(api, node, context)
            return
        param = self.project.string(
            call_argument(node, api.name), context.scope)
        if param is None:
            return
        namespace = '~' if api.node_private else ''
        if param.startswith('~'):
            # rospy: a private parameter
            param, namespace = param[1:], '~'
        default = self.project.string(
            call_argument(node, api.default), context.scope)
        fact_builder.add_param_read(
            self.facts, function=context.function, name=param, default=default,
            handle=self._param_handle(node, context.scope), nh=namespace,
            location=self.location(node))

    def _param_list(self, api, node, context):
        """``declare_parameters('ns', [('topic', 'scan'), ...])``.

        Each parameter whose name is known, with its default when it is a
        known string; a later ``get_parameter('ns.topic')`` takes it.
        """
        prefix = self.project.string(
            call_argument(node, api.param_namespace), context.scope)
        if prefix is None and call_argument(node, api.param_namespace):
            return  # a namespace not known: no name is known
        for entry in self._elements(
                call_argument(node, api.param_list), context):
            if not isinstance(entry, (ast.Tuple, ast.List)) or \
                    not entry.elts:
                continue
            param = self.project.string(entry.elts[0], context.scope)
            if param is None:
                continue
            default = self.project.string(entry.elts[1], context.scope) \
                if len(entry.elts) > 1 else None
            fact_builder.add_param_read(
                self.facts, function=context.function,
                name=f'{prefix}.{param}' if prefix else param,
                default=default,
                handle=self._param_handle(entry, context.scope), nh='~',
                location=self.location(entry))
