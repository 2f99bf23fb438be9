# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What code says about the process that hosts it, or that it hosts.

Two roles of :mod:`colcon_rsia.frontend.ros_api`, dispatched through the
walker's table like those of :mod:`colcon_rsia.frontend.cpp.roles`:

- ``HOST_EVENT``: a callback the hosting process calls on an event of its
  own (gzserver's world update, ``ConnectWorldUpdateBegin(cb)``). Which
  events come at a rate of the host's is the host table's business
  (:mod:`colcon_rsia.package.plugin_hosts`).
- ``NODELET_LOAD``: ``nodelet::Loader::load(name, type, ...)``, a nodelet
  instance the process starts itself, under the name given there.
"""

import clang.cindex as ci
from colcon_rsia.frontend import fact_builder
from colcon_rsia.frontend import ros_api
from colcon_rsia.frontend.cpp.cursors import first_handle
from colcon_rsia.frontend.cpp.cursors import qualified_name
from colcon_rsia.frontend.cpp.cursors import role_argument
from colcon_rsia.frontend.cpp.cursors import walk_preorder
from colcon_rsia.frontend.cpp.cursors import written_arguments
from colcon_rsia.frontend.cpp.strings import unquote
from colcon_rsia.frontend.cpp.strings import written_name

CK = ci.CursorKind


class HostedRoles:
    """The handlers of the hosting roles, for one walk."""

    def __init__(self, facts, places, *, resolve_callback):  # noqa: D107
        # the unit's facts, where cursors are (questions.Places), and
        # (function id, declaration) of a callback argument
        self.facts = facts
        self.places = places
        self.resolve_callback = resolve_callback

    def handlers(self):
        """The walker's handlers for the roles of this module."""
        return {
            ros_api.HOST_EVENT: self._on_host_event,
            ros_api.NODELET_LOAD: self._on_nodelet_load,
        }

    def _on_host_event(self, cursor, ctx, stack, api, name, arguments):
        callback, _ = self.resolve_callback(
            role_argument(arguments, api.callback_arg))
        fact_builder.add_host_event(
            self.facts, function=ctx.function, api=name, callback=callback,
            location=self.places.location(cursor))

    def _on_nodelet_load(self, cursor, ctx, stack, api, name, arguments):
        nodelet_name, name_known = written_name(
            role_argument(arguments, api.name_arg))
        nodelet_type, type_known = written_name(
            role_argument(arguments, api.type_name_arg))
        fact_builder.add_nodelet_load(
            self.facts, function=ctx.function,
            name=nodelet_name if name_known else None,
            type=nodelet_type if type_known else None,
            location=self.places.location(cursor))


def node_handle_marker(argument):
    """The namespace marker of a NodeHandle made in place, or None.

    What a nodelet hands its helper classes: ``Driver(getNodeHandle(),
    getPrivateNodeHandle())`` passes its public ('') and private ('~')
    handles; ``ros::NodeHandle("~")`` and ``ros::NodeHandle()`` made as
    arguments are the private handle and the node's. An argument naming a
    variable is a handle of its own (None here).
    """
    if argument is None or first_handle(argument) is not None:
        return None
    for current in [argument] + list(walk_preorder(
            argument, stop=frozenset({CK.LAMBDA_EXPR}))):
        if current.kind != CK.CALL_EXPR or current.referenced is None:
            continue
        api = ros_api.lookup_call(qualified_name(current.referenced))
        if api is None:
            return None
        if api.role == ros_api.PRIVATE_HANDLE:
            return '~'
        if api.role == ros_api.PUBLIC_HANDLE:
            return ''
        if api.role != ros_api.NODE_HANDLE:
            return None
        written = written_arguments(list(current.get_arguments()))
        if not written:
            return ''
        literals = [c for c in [written[0]] + list(walk_preorder(written[0]))
                    if c.kind == CK.STRING_LITERAL]
        if len(written) == 1 and len(literals) == 1:
            return unquote(literals[0].spelling)
        # a copy of another handle (NodeHandle(getPrivateNodeHandle())):
        # the handle inside decides
    return None
