# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Clocks beyond ROS: Qt timers, boost::asio timers, fixed-rate loops.

Each is read into the facts the ROS APIs give (a timer whose callback is a
timer root, a loop paced like a ``ros::Rate`` loop), so labelling knows
nothing of them:

- Qt: ``connect(timer, &QTimer::timeout, receiver, &C::slot)`` (also
  ``SIGNAL(timeout())``/``SLOT(slot())`` and a functor) makes the slot the
  callback of that QTimer object, whose interval comes from ``start(ms)`` /
  ``setInterval(ms)`` on the same object; ``setSingleShot(true)`` makes it
  fire once, so it is no clock. ``QObject::startTimer(ms)`` calls the
  object's ``timerEvent()``.
- boost::asio: ``timer.async_wait(handler)`` is periodic when the handler
  arms the same timer again (its own body, or the function a lambda
  handler calls, waits on that timer); the period comes from the timer's
  constructor and its ``expires_*`` calls. A handler that does not re-arm
  runs once: it stays an ordinary reference from where it was armed.
- ``sleep_until(next)`` paces its loop like ``Rate::sleep()`` when the loop
  advances ``next`` by a fixed period (``next += period``); a deadline that
  never moves paces nothing.

The connections and periods of a timer object are often set in different
statements, so they are gathered during the walk and joined at its end
(:meth:`OtherClocks.finish`), within the translation unit.
"""

from dataclasses import dataclass
import re

import clang.cindex as ci
from colcon_rsia.frontend import fact_builder
from colcon_rsia.frontend import recorder
from colcon_rsia.frontend import ros_api
from colcon_rsia.frontend.cpp.const_eval import evaluate_number
from colcon_rsia.frontend.cpp.const_eval import evaluate_period_seconds
from colcon_rsia.frontend.cpp.cursors import call_arguments
from colcon_rsia.frontend.cpp.cursors import call_object
from colcon_rsia.frontend.cpp.cursors import child_cursors
from colcon_rsia.frontend.cpp.cursors import CLASS_KINDS
from colcon_rsia.frontend.cpp.cursors import expression_text
from colcon_rsia.frontend.cpp.cursors import first_function
from colcon_rsia.frontend.cpp.cursors import first_handle
from colcon_rsia.frontend.cpp.cursors import FUNCTION_KINDS
from colcon_rsia.frontend.cpp.cursors import qualified_name
from colcon_rsia.frontend.cpp.cursors import role_argument
from colcon_rsia.frontend.cpp.cursors import walk_preorder
from colcon_rsia.frontend.cpp.questions import paced_loop
from colcon_rsia.frontend.cpp.questions import record_paced_loop
from colcon_rsia.frontend.cpp.questions import stored_target

CK = ci.CursorKind

QT_TIMEOUT_SIGNAL = 'QTimer::timeout'
QT_TIMER_EVENT = 'timerEvent'
_SLOT_MACRO = re.compile(r'\bSLOT\s*\(\s*(\w+)\s*\(')
_SIGNAL_MACRO = re.compile(r'\bSIGNAL\s*\(\s*(\w+)\s*\(')


@dataclass
class _Wait:
    """One ``async_wait(handler)`` on a boost::asio timer."""

    timer: str          # the timer object's USR
    callback: str       # the handler's function id
    function: str       # the function the wait is in
    reaches: frozenset  # the handler and the functions a lambda one calls
    api: str
    location: str
    loops: list


class OtherClocks:
    """The non-ROS clocks of one translation unit."""

    def __init__(self, facts, places, *, resolve_callback):  # noqa: D107
        # the unit's facts, where cursors are (questions.Places), and
        # (function id, declaration) of a callback argument
        self.facts = facts
        self.places = places
        self.resolve_callback = resolve_callback
        # (timer fact, QTimer object USR)
        self._connected = []
        # timer object USR -> {(period as written, Hz or None)}
        self._periods = {}
        self._single_shot = set()
        self._waits = []

    def handlers(self):
        """The walker's handlers for the roles this module reads."""
        return {
            ros_api.SIGNAL_CONNECT: self._on_signal_connect,
            ros_api.TIMER_PERIOD: self._on_timer_period,
            ros_api.TIMER_SINGLE_SHOT: self._on_single_shot,
            ros_api.OBJECT_TIMER: self._on_object_timer,
            ros_api.TIMER_WAIT: self._on_timer_wait,
            ros_api.DEADLINE_SLEEP: self._on_deadline_sleep,
        }

    # --- Qt ----------------------------------------------------------------

    def _on_signal_connect(self, cursor, ctx, stack, api, name, arguments):
        if len(arguments) < 3:
            return
        sender = first_handle(arguments[0])
        # SIGNAL(timeout()) and SLOT(name()) expand to strings: their names
        # are read from the call as written
        written = expression_text(cursor)
        if sender is None or not _is_timeout(arguments[1], written):
            return
        sender_class = _class_of(arguments[0])
        if sender_class is None or qualified_name(sender_class) != 'QTimer':
            return  # another class's timeout() signal is no clock
        callback = self._slot(arguments, written)
        if callback is None:
            return
        fact = fact_builder.add_timer(
            self.facts, function=ctx.function, api=api.label,
            callback=callback, period='', rate_hz=None,
            location=self.places.location(cursor))
        self._connected.append((fact, sender.get_usr()))

    def _slot(self, arguments, written):
        """The function id a connection calls, or None."""
        receiver = arguments[2]
        slot_name = _SLOT_MACRO.search(written)
        if slot_name is None:
            # connect(sender, signal, functor) or (..., receiver, &C::slot)
            slot = role_argument(arguments, 3) or receiver
            callback, _ = self.resolve_callback(slot)
            return callback
        # SLOT(name()): the receiver's method of that name
        method = _method_of(_class_of(receiver), slot_name.group(1))
        if method is None or not self.places.in_package(method):
            return None
        return method.get_usr()

    def _on_timer_period(self, cursor, ctx, stack, api, name, arguments):
        if cursor.referenced is not None and \
                cursor.referenced.kind == CK.CONSTRUCTOR:
            timer = stored_target(cursor, stack)
        else:
            timer = first_handle(call_object(cursor))
        period = role_argument(arguments, api.period_arg)
        if timer is None or period is None:
            return
        seconds = _period_seconds(period, api.period_unit)
        if seconds is None and _is_time_point(period):
            return  # an absolute deadline says nothing of a period
        self._periods.setdefault(timer.get_usr(), set()).add(
            (expression_text(period), recorder.rate_of_period(seconds)))

    def _on_single_shot(self, cursor, ctx, stack, api, name, arguments):
        timer = first_handle(call_object(cursor))
        value = role_argument(arguments, 0)
        if timer is not None and value is not None and \
                expression_text(value) in ('true', '1'):
            self._single_shot.add(timer.get_usr())

    def _on_object_timer(self, cursor, ctx, stack, api, name, arguments):
        """``startTimer(ms)``: the object's timerEvent() every interval."""
        obj = call_object(cursor)
        owner = _class_of(obj) if obj is not None else ctx.owner
        method = _method_of(owner, QT_TIMER_EVENT)
        if method is None or not self.places.in_package(method):
            return
        period = role_argument(arguments, api.period_arg)
        seconds = _period_seconds(period, api.period_unit) \
            if period is not None else None
        fact_builder.add_timer(
            self.facts, function=ctx.function, api=name, callback=method.get_usr(),
            period=expression_text(period) if period is not None else '',
            rate_hz=recorder.rate_of_period(seconds), location=self.places.location(cursor))

    # --- boost::asio ---------------------------------------------------------

    def _on_timer_wait(self, cursor, ctx, stack, api, name, arguments):
        timer = first_handle(call_object(cursor))
        callback, declaration = self.resolve_callback(
            role_argument(arguments, api.callback_arg))
        if timer is None or callback is None:
            return
        reaches = {callback}
        if declaration is not None and declaration.kind == CK.LAMBDA_EXPR:
            reaches |= _called_functions(declaration)
        self._waits.append(_Wait(
            timer=timer.get_usr(), callback=callback, function=ctx.function,
            reaches=frozenset(reaches), api=api.label,
            location=self.places.location(cursor), loops=ctx.loop_ids()))

    # --- fixed-rate loops --------------------------------------------------

    def _on_deadline_sleep(self, cursor, ctx, stack, api, name, arguments):
        deadline = first_handle(role_argument(arguments, 0))
        if deadline is None:
            return
        paced = paced_loop(ctx, cursor, deadline)
        if paced is None:
            return
        loop_id, loop = paced
        step = _advance(loop, deadline)
        if step is None:
            return  # a deadline that never moves
        fact_builder.add_rate(
            self.facts, handle=deadline.get_usr(),
            rate_hz=recorder.rate_of_period(_period_seconds(step, 1.0)),
            expression=expression_text(step),
            location=self.places.location(step))
        record_paced_loop(
            self.facts, self.places.location, ctx, loop_id=loop_id,
            loop=loop, clock=deadline, sleep=cursor)

    # --- the end of the unit -----------------------------------------------

    def finish(self):
        """Join connections, periods and waits gathered during the walk."""
        facts = self.facts
        for fact, timer in self._connected:
            if timer in self._single_shot:
                # fires once: called from where it is connected
                facts.timers.remove(fact)
                fact_builder.add_call(
                    facts, caller=fact.function, callee=fact.callback,
                    location=fact.location, loops=[], kind='ref')
                continue
            fact.period, fact.rate_hz = self._period_of(timer)
        added = set()
        for wait in self._waits:
            rearmed = any(other.timer == wait.timer and
                          other.function in wait.reaches
                          for other in self._waits)
            if not rearmed:
                fact_builder.add_call(
                    facts, caller=wait.function, callee=wait.callback,
                    location=wait.location, loops=wait.loops, kind='ref')
                continue
            if (wait.timer, wait.callback) in added:
                continue
            added.add((wait.timer, wait.callback))
            period, rate_hz = self._period_of(wait.timer)
            fact_builder.add_timer(
                facts, function=wait.function, api=wait.api,
                callback=wait.callback, period=period, rate_hz=rate_hz,
                location=wait.location)

    def _period_of(self, timer):
        """(period as written, Hz) of a timer object.

        Hz only when every period set on it is the same constant.
        """
        periods = sorted(self._periods.get(timer, ()),
                         key=lambda p: (p[0], p[1] or 0))
        rates = {hz for _, hz in periods}
        text = ' | '.join(written for written, _ in periods)
        return text, rates.pop() if len(rates) == 1 else None


def connects_timer(cursor):
    """Whether a connect() call names QTimer's timeout() signal.

    A `connect` known by its name alone (its class unknown to the parse)
    is Qt's only then; any other is left to be what the package's code
    makes of it.
    """
    arguments = call_arguments(cursor)
    return len(arguments) >= 3 and _is_timeout(
        arguments[1], expression_text(cursor))


def _is_timeout(signal, written):
    """Whether a connect() call names QTimer's timeout() signal."""
    signal_name = _SIGNAL_MACRO.search(written)
    if signal_name is not None:
        return signal_name.group(1) == 'timeout'
    function = first_function(signal)
    return function is not None and \
        qualified_name(function) == QT_TIMEOUT_SIGNAL


def _class_of(expression):
    """The class declaration of an object expression (``this``, ``&obj``)."""
    if expression is None:
        return None
    # the object as written, not its conversion to a base class pointer
    # (`this` passed as the `const QObject *` of connect)
    while expression.kind == CK.UNEXPOSED_EXPR:
        children = child_cursors(expression)
        if len(children) != 1:
            break
        expression = children[0]
    type_ = expression.type.get_canonical()
    if type_.kind == ci.TypeKind.POINTER:
        type_ = type_.get_pointee()
    declaration = type_.get_declaration()
    return declaration if declaration.kind in CLASS_KINDS else None


def _method_of(owner, name):
    """The method `name` declared in class `owner`, or None."""
    if owner is None:
        return None
    for child in owner.get_children():
        if child.kind in FUNCTION_KINDS and child.spelling == name:
            return child
    return None


def _called_functions(lambda_expression):
    """USRs of the functions a lambda's body calls directly."""
    called = set()
    for current in walk_preorder(lambda_expression):
        if current.kind == CK.CALL_EXPR and current.referenced is not None \
                and current.referenced.kind in FUNCTION_KINDS:
            called.add(current.referenced.get_usr())
    return called


def _period_seconds(argument, unit):
    """Seconds of a period argument, or None when not a constant.

    A duration of any clock library, a bare number counting `unit`
    seconds, or the duration added to a time point (``expires_at(expiry()
    + 50ms)``).
    """
    added = _added_duration(argument)
    if added is not None:
        return _period_seconds(added, unit)
    seconds = evaluate_period_seconds(argument)
    if seconds is not None:
        return seconds
    value = evaluate_number(argument)
    return value * unit if value is not None else None


def _added_duration(expression):
    """`d` of an expression ``t + d``, or None."""
    for current in [expression] + list(walk_preorder(expression)):
        if current.kind == CK.CALL_EXPR and current.spelling == 'operator+':
            operands = list(current.get_arguments())
            return operands[-1] if len(operands) == 2 else None
        if current.kind not in (CK.UNEXPOSED_EXPR, CK.PAREN_EXPR):
            return None
    return None


def _is_time_point(argument):
    canonical = argument.type.get_canonical().spelling
    return 'time_point' in canonical or 'ptime' in canonical


def _advance(loop, deadline):
    """The period a loop adds to `deadline` (``next += period``), or None."""
    usr = deadline.get_usr()
    for current in walk_preorder(loop, stop=frozenset({CK.LAMBDA_EXPR})):
        if current.kind == CK.CALL_EXPR and current.spelling == 'operator+=':
            operands = list(current.get_arguments())
        elif current.kind == CK.COMPOUND_ASSIGNMENT_OPERATOR:
            operands = child_cursors(current)
        elif current.kind == CK.CALL_EXPR and \
                current.spelling == 'operator=':
            # next = next + period
            operands = list(current.get_arguments())
            if len(operands) == 2:
                operands[1] = _added_duration(operands[1])
        else:
            continue
        if len(operands) != 2 or operands[1] is None:
            continue
        target = first_handle(operands[0])
        if target is not None and target.get_usr() == usr:
            return operands[1]
    return None
