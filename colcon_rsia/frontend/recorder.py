# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What both front ends record the same way: where a walk is, what paces.

The C++ and the Python front end answer syntax questions (is this a loop,
a branch, a `continue`; where was this clock made); this module owns the
rules they feed: the loop context a call is made in, and when a sleep paces
its loop, with the fact that says so. One place, so the languages cannot
drift apart again (see tests/frontend/test_cpp_python_parity.py).
"""

from contextlib import contextmanager

from colcon_rsia.frontend import fact_builder


class Context:
    """Where a walk is inside one function body.

    ``loops`` holds (loop id, conditional depth at the loop, loop syntax
    node) from the outermost; ``conditional`` counts the branches around the
    current statement that may not run (if/else, switch/match, handlers,
    the right operand of ``||``/``or``, the arms of ``?:``).
    """

    def __init__(  # noqa: D107
            self, function, *, owner=None, scope=None, loops=(),
            conditional=0):
        self.function = function
        # C++: the class of a method (a lambda's: its enclosing method's)
        self.owner = owner
        # Python: the scope names are looked up in
        self.scope = scope
        self.loops = list(loops)
        self.conditional = conditional

    def loop_ids(self):
        """The ids of the loops around the current statement."""
        return [loop_id for loop_id, _, _ in self.loops]

    @contextmanager
    def loop(self, loop_id, node):
        """Inside the body of a loop."""
        self.loops.append((loop_id, self.conditional, node))
        try:
            yield
        finally:
            self.loops.pop()

    @contextmanager
    def branch(self):
        """Inside code that may not run every time."""
        self.conditional += 1
        try:
            yield
        finally:
            self.conditional -= 1


def paced_loop(context, *, made_in_loop, continue_before):
    """(loop id, loop node) a sleep paces, or None.

    A sleep paces its innermost loop when it runs on every iteration (not
    in a branch of it, no `continue` of it before) and its clock (a Rate,
    a deadline) outlives the iteration: one made anew in every iteration
    never adapts. The front end answers, for the loop node:
    `made_in_loop(loop)` and `continue_before(loop)`.
    """
    if not context.loops:
        return None
    loop_id, conditional_at_entry, loop = context.loops[-1]
    if context.conditional != conditional_at_entry:
        return None
    if continue_before(loop) or made_in_loop(loop):
        return None
    return loop_id, loop


def round_rate(hz):
    """A rate as a person would write it: 1/0.1 is 10, not 9.99…."""
    return round(float(hz), 6) if hz is not None else None


def rate_of_period(seconds):
    """The rate of a period in seconds (None for none or zero)."""
    return round_rate(1.0 / seconds) if seconds else None


def record_paced_loop(facts, context, *, loop_id, clock, loop_location,
                      sleep_location):
    """The fact that a loop runs at the pace of `clock` (a handle)."""
    fact_builder.add_paced_loop(
        facts, loop=loop_id, function=context.function, rate_handle=clock,
        location=loop_location, sleep_location=sleep_location)
