# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Tables of handlers that the handlers register themselves in.

The launch readers and the executor dispatch by key: an element's tag,
an action's or a value's type. Each handler says what it handles where it
is written::

    _ELEMENTS = HandlerTable('element')

    class Reader:
        @_ELEMENTS.handles('node', 'lifecycle_node')
        def _node(self, elem):
            ...

        def element(self, elem):
            handler = _ELEMENTS.get(elem.tag)
            ...
            return handler(self, elem)

so that reading one more kind of thing is one more decorated method. A
method is registered as the plain function it is in the class body: the
caller passes the instance. Imports nothing, like
:mod:`colcon_rsia.launch.notes`.
"""


class HandlerTable:
    """Handlers by key, each registered once by a decorator."""

    def __init__(self, what):
        """Make an empty table.

        :param str what: what a key is, for the message of a key
          registered twice ('element', 'action type')
        """
        self.what = what
        self._handlers = {}

    def handles(self, *keys):
        """Register the decorated function as the handler of ``keys``.

        :raises ValueError: when a key has a handler already (two handlers
          of one key: the second would silently win)
        """
        def register(function):
            for key in keys:
                if key in self._handlers:
                    raise ValueError(
                        f'{self.what} {_key_text(key)} has two handlers: '
                        f'{self._handlers[key].__name__} and '
                        f'{function.__name__}')
            for key in keys:
                self._handlers[key] = function
            return function
        return register

    def get(self, key, default=None):
        """The handler of ``key``, or ``default`` when it has none."""
        return self._handlers.get(key, default)

    def __getitem__(self, key):
        """The handler of ``key``; KeyError when it has none."""
        return self._handlers[key]

    def __contains__(self, key):
        """Whether ``key`` has a handler."""
        return key in self._handlers

    def keys(self):
        """The keys with a handler, in the order they were registered."""
        return list(self._handlers)


def _key_text(key):
    return key.__name__ if isinstance(key, type) else repr(key)
