# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What the C++ walker's helpers ask about the cursors of one walk.

The walker (:mod:`colcon_rsia.frontend.cpp.walker`) hands its helpers
(:mod:`.roles`, :mod:`.hosted`, :mod:`.clocks`, :mod:`.wrappers`,
:mod:`.strings`, :mod:`.callbacks`) the narrow things they use, never
itself: the unit's facts, a :class:`Places` (where a cursor is: the
package's files, its location, the unit's ROS version) and the functions
of this module, which answer from the cursors and the expression stack
alone. The rules both front ends share stay the recorder's
(:mod:`colcon_rsia.frontend.recorder`): these answer its questions about
the C++ syntax.
"""

import os

import clang.cindex as ci
from colcon_rsia.frontend import fact_builder
from colcon_rsia.frontend import recorder
from colcon_rsia.frontend import ros_api
from colcon_rsia.frontend.cpp.const_eval import binary_operator
from colcon_rsia.frontend.cpp.const_eval import source_tokens
from colcon_rsia.frontend.cpp.cursors import call_arguments
from colcon_rsia.frontend.cpp.cursors import call_object
from colcon_rsia.frontend.cpp.cursors import child_cursors
from colcon_rsia.frontend.cpp.cursors import continue_before
from colcon_rsia.frontend.cpp.cursors import declared_in
from colcon_rsia.frontend.cpp.cursors import first_handle
from colcon_rsia.frontend.cpp.cursors import STATEMENT_KINDS
from colcon_rsia.frontend.cpp.cursors import top_level_scopes
from colcon_rsia.frontend.cpp.cursors import written_arguments
from colcon_rsia.frontend.cpp.every_nth import every_nth
from colcon_rsia.frontend.cpp.model_mode.headers import MODEL_HEADERS_DIR

CK = ci.CursorKind


class MemberInit:
    """Stands on the expression stack for a constructor's member init."""

    kind = None

    def __init__(self, member):  # noqa: D107
        self.member = member


class Places:
    """Where the cursors of one unit are, and the unit's ROS version.

    Read-only for the helpers; the walker sets :attr:`ros2` once it has
    seen the unit.
    """

    def __init__(self, package_path):  # noqa: D107
        self.package_path = package_path.rstrip('/') + '/'
        # a ROS 2 unit: some APIs keep their ROS 1 names but behave
        # differently
        self.ros2 = False
        self._in_package_cache = {}

    def in_package(self, cursor):
        """Whether a cursor is in a file of the package."""
        file = cursor.location.file
        if file is None:
            return False
        name = file.name
        cached = self._in_package_cache.get(name)
        if cached is None:
            cached = os.path.abspath(name).startswith(self.package_path)
            self._in_package_cache[name] = cached
        return cached

    def is_workspace_declaration(self, cursor):
        """Whether a declaration is in another package of the workspace.

        Its body is the workspace's code: not a system, model or stand-in
        header.
        """
        file = cursor.location.file
        if file is None:
            return False
        name = os.path.abspath(file.name)
        return not name.startswith(('/usr/', '/opt/', MODEL_HEADERS_DIR)) \
            and '/rsia/stubs/' not in name and '/rsia_model/' not in name

    def relpath(self, cursor):
        """The path of a cursor's file (see :meth:`relative_path`)."""
        return self.relative_path(cursor.location.file.name)

    def relative_path(self, file_name):
        """A file's path relative to the package (absolute outside it)."""
        name = os.path.abspath(file_name)
        if name.startswith(self.package_path):
            return name[len(self.package_path):]
        return name

    def location(self, cursor):
        """``file:line`` of a cursor, ``?:0`` for none."""
        if cursor.location.file is None:
            return '?:0'
        return f'{self.relpath(cursor)}:{cursor.location.line}'

    def key(self, cursor):
        """What tells one expression of the unit from another."""
        file = cursor.location.file
        return (file.name if file else '', cursor.extent.start.offset)

    def loop_id(self, cursor):
        """The id of a loop statement."""
        return f'{self.relpath(cursor)}@{cursor.extent.start.offset}'

    def lambda_id(self, cursor):
        """The function id of a lambda expression."""
        loc = cursor.location
        return f'lambda@{self.relpath(cursor)}:{loc.line}:{loc.column}'

    def table_msg_type(self, msg_type):
        """A message type the API table spells the ROS 1 way, for this unit.

        ROS 2 spells ``sensor_msgs::Image`` as ``sensor_msgs::msg::Image``.
        """
        if not msg_type or not self.ros2 or '::msg::' in msg_type:
            return msg_type
        package, _, name = msg_type.partition('::')
        return f'{package}::msg::{name}'


def stored_target(cursor, stack):
    """The variable/field a created object is stored in, or None."""
    start = cursor.extent.start.offset
    for parent in reversed(stack):
        if isinstance(parent, MemberInit):
            return parent.member
        kind = parent.kind
        if kind == CK.VAR_DECL:
            return parent
        if kind in STATEMENT_KINDS:
            return None
        if kind == CK.CALL_EXPR:
            children = child_cursors(parent)
            if parent.spelling == 'operator=' and children:
                return first_handle(children[0])
            obj = call_object(parent)
            if obj is not None and obj.extent.end.offset <= start:
                # x.reset(new ...), v.push_back(nh.advertise(...))
                return first_handle(obj)
        if kind == CK.BINARY_OPERATOR:
            children = child_cursors(parent)
            if children and binary_operator(parent, children[0]) == '=':
                return first_handle(children[0])
    return None


def dependent_call_name(cursor, *, ros2):
    """The API a call on a template-dependent object names, or None."""
    children = child_cursors(cursor)
    callee = children[0] if children else None
    while callee is not None and callee.kind == CK.UNEXPOSED_EXPR:
        # (a static member's, decayed to a pointer: the catch-all's
        # member templates are static)
        inner = child_cursors(callee)
        callee = inner[0] if len(inner) == 1 else None
    if callee is None or callee.kind not in (
            CK.MEMBER_REF_EXPR, CK.DECL_REF_EXPR, CK.OVERLOADED_DECL_REF):
        return None
    # a dependent member has no spelling: the name follows `.`/`->`,
    # or the last `::` of `Base::create_publisher<M>(…)` (this->), or
    # starts the callee (a member of the object itself, a function the
    # model's catch-alls declare)
    tokens = [t.spelling for t in source_tokens(callee)]
    accesses = [i for i, t in enumerate(tokens) if t in ('.', '->')] or \
        top_level_scopes(tokens)
    start = accesses[-1] + 1 if accesses else 0
    rest = [t for t in tokens[start:] if t != 'template']
    if not rest:
        return None
    return ros_api.dependent_method(
        rest[0], ros2=ros2, arguments=len(written_arguments(
            call_arguments(cursor))))


def paced_loop(ctx, sleep, clock):
    """(loop id, loop cursor) a sleep on `clock` paces, or None.

    The rule is the recorder's (:func:`recorder.paced_loop`); this
    answers its questions about the C++ syntax.
    """
    if clock is None:
        return None
    return recorder.paced_loop(
        ctx, continue_before=lambda loop: continue_before(loop, sleep),
        made_in_loop=lambda loop: declared_in(clock, loop))


def record_paced_loop(facts, location, ctx, *, loop_id, loop, clock, sleep):
    """Record that `loop` runs at the pace of the `clock` handle."""
    recorder.record_paced_loop(
        facts, ctx, loop_id=loop_id, clock=clock.get_usr(),
        loop_location=location(loop), sleep_location=location(sleep))


def record_publish_site(facts, location, ctx, stack, cursor, api, handle):
    """Record a publish call through `handle` (a USR) at `cursor`."""
    fact_builder.add_publish_site(
        facts, function=ctx.function, api=api, handle=handle,
        location=location(cursor), loops=ctx.loop_ids(),
        every=every_nth(stack + [cursor]))
