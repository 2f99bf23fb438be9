# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The facts a call read from tokens makes, by the role of its API.

A part of the token reader (:mod:`token_facts`): its ``_Reader`` finds a
call the AST lost and what API it stands for, and sets ``_current`` (the
call's index, start, object, template arguments, API, name and the
declaration it may be stored by); these methods turn that call into the
fact the AST would have made (``origin='tokens'``).
"""

import re

import clang.cindex as ci
from colcon_rsia.frontend import fact_builder
from colcon_rsia.frontend import recorder
from colcon_rsia.frontend import ros_api
from colcon_rsia.frontend.cpp.cursors import normalize_msg_type
from colcon_rsia.frontend.cpp.token_text import arithmetic
from colcon_rsia.frontend.cpp.token_text import joined_text
from colcon_rsia.frontend.cpp.token_text import seconds_of
from colcon_rsia.frontend.cpp.token_text import tokens_of
from colcon_rsia.summary.kinds import ORIGIN_TOKENS

CK = ci.CursorKind
TOKENS = ORIGIN_TOKENS
# calls that store their argument in their object
STORING_METHODS = frozenset({
    'push_back', 'emplace_back', 'reset', 'insert', 'emplace', 'push',
    'push_front', 'emplace_front', 'assign'})


class CallFacts:
    """The role handlers of the token reader (a mixin of ``_Reader``).

    They read the reader's tokens, its current call and its helpers
    (``_argument``, ``_topic``, ``_handle``, ``_callback``, ``_location``).
    """

    def _msg_type(self, arguments, callback_declaration=None):
        api = self._current['api']
        if api.msg_type:
            return self._table_msg_type(api.msg_type)
        if api.type_name_arg is not None:
            written, literal, _ = self._topic(
                self._argument(arguments, api.type_name_arg))
            if literal and re.fullmatch(r'\w+/\w+/\w+', written or ''):
                return written.replace('/', '::')
        template = self._current['template']
        if template is not None:
            tokens = self.tokens[template[0]:template[1]]
            depth = 0
            first = []
            for token in tokens:
                depth += {'<': 1, '>': -1, '>>': -2}.get(token.text, 0)
                if token.text == ',' and depth == 0:
                    break
                first.append(token)
            return normalize_msg_type(joined_text(first))
        return self._parameter_type(callback_declaration)

    def _table_msg_type(self, msg_type):
        if not msg_type or not self.ros2 or '::msg::' in msg_type:
            return msg_type
        package, _, name = msg_type.partition('::')
        return f'{package}::msg::{name}'

    def _parameter_type(self, declaration):
        """The message type of a callback's first parameter, as written."""
        if declaration is None:
            return None
        for child in declaration.get_children():
            if child.kind != CK.PARM_DECL:
                continue
            written = [t for t in tokens_of(self.tu, child.extent)
                       if t.text != child.spelling]
            return normalize_msg_type(joined_text(written)) or \
                normalize_msg_type(child.type.spelling)
        return None

    def _target(self):
        """(id, name) of the variable or member a call's result goes to."""
        tokens = self.tokens
        start = self._current['start']
        target = self._current['target']
        j = start - 1
        if j >= 0 and tokens[j].text == '=':
            k = j - 1
            while k >= 0 and tokens[k].text == ']' and k in self.pairs:
                k = self.pairs[k] - 1
            if k >= 0 and tokens[k].kind == 'IDENTIFIER':
                return self._handle(tokens[k].text)[0], tokens[k].text
            return None, None
        if j >= 1 and tokens[j].text in ('(', '{') and \
                tokens[j - 1].kind == 'IDENTIFIER':
            name = tokens[j - 1].text
            if name in STORING_METHODS:
                handle, _ = self._object_name(self._object(j - 1))
                names = [t for t in tokens[(self._object(j - 1) or (j, j))[0]:
                                           j - 2] if t.kind == 'IDENTIFIER']
                return handle, names[-1].text if names else None
            if self._declares(j - 1) or (target and target[0] == j - 1):
                return self._handle(name)[0], name
        if target is not None and target[0] == start - 2:
            return self._handle(target[1])[0], target[1]
        return None, None

    def _namespace(self):
        """The NodeHandle (or namespace marker) a create call was made on."""
        object_range = self._current['object']
        if object_range is None:
            return None
        texts = [t.text for t in self.tokens[object_range[0]:object_range[1]]]
        for text in texts:
            api = ros_api.lookup_call(f'nodelet::Nodelet::{text}')
            if api is not None and api.role == ros_api.PRIVATE_HANDLE:
                return '~'
            if api is not None and api.role == ros_api.PUBLIC_HANDLE:
                return ''
        return self._object_handle(object_range)

    # --- facts -------------------------------------------------------------

    def _here(self):
        return self._location(self._current['start'])

    def _is_recorded(self, role):
        return self._here() in self.recorded[role]

    def _endpoint(self, arguments, ctx, callback_declaration=None):
        api = self._current['api']
        topic, literal, topic_handle = self._topic(
            self._argument(arguments, api.name_arg))
        handle, handle_name = self._target()
        return dict(
            function=ctx.function, api=ros_api.api_label(self._current['name']),
            topic=topic, topic_is_literal=literal,
            msg_type=self._msg_type(arguments, callback_declaration),
            handle=handle, location=self._here(), nh=self._namespace(),
            topic_handle=topic_handle, origin=TOKENS), handle_name

    def _publisher(self, arguments, ctx):
        if self._is_recorded('publisher'):
            return
        common, handle_name = self._endpoint(arguments, ctx)
        if common['topic'] is None:
            return  # a constructor without a name: init() gives it later
        status_callbacks = [
            callback for position in self._current['api'].status_callback_args
            for callback in [self._callback(
                self._argument(arguments, position), ctx)[0]] if callback]
        fact_builder.add_publisher(
            self.facts, handle_name=handle_name, status_callbacks=status_callbacks,
            **common)

    def _subscriber(self, arguments, ctx):
        if self._is_recorded('subscriber'):
            return
        api = self._current['api']
        callback, declaration = self._callback(
            self._argument(arguments, api.callback_arg), ctx) \
            if api.callback_arg is not None else (None, None)
        common, _ = self._endpoint(arguments, ctx, declaration)
        if common['topic'] is None:
            return
        fact_builder.add_subscriber(
            self.facts, callback=callback, **common)

    def _timer(self, arguments, ctx):
        if self._is_recorded('timer'):
            return
        api = self._current['api']
        callback, _ = self._callback(
            self._argument(arguments, api.callback_arg), ctx)
        period = self._argument(arguments, api.period_arg)
        tokens = self.tokens[period[0]:period[1]] if period else []
        seconds = seconds_of(tokens)
        if seconds is not None:
            seconds *= api.period_unit
        fact_builder.add_timer(
            self.facts, function=ctx.function, api=ros_api.api_label(self._current['name']),
            callback=callback, period=joined_text(tokens),
            rate_hz=recorder.rate_of_period(seconds), location=self._here(),
            origin=TOKENS)

    def _signal_connect(self, arguments, ctx):
        """``connect(timer_, &QTimer::timeout, this, &C::tick)``: a timer.

        Only a connection of QTimer's timeout() signal, named by its
        member pointer (the tokens know no sender's class). Its interval
        is what ``start(ms)`` or ``setInterval(ms)`` on the same object
        gives in this function; unknown otherwise.
        """
        if self._is_recorded('timer') or len(arguments) < 3:
            return
        signal = joined_text(self.tokens[slice(*arguments[1])])
        if re.sub(r'\s+', '', signal).lstrip('&') != 'QTimer::timeout':
            return
        callback, _ = self._callback(
            arguments[3] if len(arguments) > 3 else arguments[2], ctx)
        if callback is None:
            return
        senders = [t.text for t in self.tokens[slice(*arguments[0])]
                   if t.kind == 'IDENTIFIER']
        period = self._qt_interval(senders[-1]) if senders else []
        seconds = seconds_of(period)
        fact_builder.add_timer(
            self.facts, function=ctx.function, api='QTimer',
            callback=callback, period=joined_text(period),
            rate_hz=recorder.rate_of_period(
                None if seconds is None else seconds * 0.001),
            location=self._here(), origin=TOKENS)

    def _qt_interval(self, timer):
        """The tokens of the interval ``timer`` is started with, or []."""
        tokens = self.tokens
        for i in range(len(tokens) - 3):
            if tokens[i].text == timer and \
                    tokens[i + 1].text in ('->', '.') and \
                    tokens[i + 2].text in ('start', 'setInterval') and \
                    tokens[i + 3].text == '(' and i + 3 in self.pairs:
                return tokens[i + 4:self.pairs[i + 3]]
        return []

    def _service(self, arguments, ctx):
        if self._is_recorded('service'):
            return
        api = self._current['api']
        name, _, _ = self._topic(self._argument(arguments, api.name_arg))
        callback, _ = self._callback(
            self._argument(arguments, api.callback_arg), ctx)
        fact_builder.add_service(
            self.facts, function=ctx.function, api=self._current['name'], name=name,
            callback=callback, location=self._here())

    def _publish(self, arguments, ctx):
        if self._is_recorded('publish'):
            return
        fact_builder.add_publish_site(
            self.facts, function=ctx.function, api=self._current['name'],
            handle=self._object_handle(self._current['object']),
            location=self._here(), loops=ctx.loop_ids(), origin=TOKENS)

    def _node_name(self, arguments, ctx):
        api = self._current['api']
        name, literal, _ = self._topic(self._argument(arguments, api.name_arg))
        if not literal or any(f.location == self._here()
                              for f in self.facts.node_names):
            return
        fact_builder.add_node_name(
            self.facts, function=ctx.function, name=name, namespace=None,
            location=self._here())

    def _rate_type(self, i):
        """Whether the declaration at `i` is of an adaptive-sleep class."""
        j = i - 1
        while j >= 0 and self.tokens[j].text in ('*', '&'):
            j -= 1
        if j < 0 or self.tokens[j].kind != 'IDENTIFIER':
            return False
        api = ros_api.lookup_call(
            self._type_before(j) + '::' + self.tokens[j].text)
        return api is not None and api.role == ros_api.RATE

    def _type_before(self, j):
        qualifier = self._qualifier(j)
        name = self.tokens[j].text
        return f'{qualifier}::{name}' if qualifier else name

    def _rate(self, i, arguments, ctx):
        """``ros::Rate r(10);``: a rate object and its rate."""
        location = self._location(i)
        handle, _ = self._handle(self.tokens[i].text) if self._declares(i) \
            else self._target()
        if handle is None or handle in self.rate_handles:
            return
        tokens = self.tokens[arguments[0][0]:arguments[0][1]] \
            if arguments else []
        hz = arithmetic([t.text for t in tokens])
        self.rate_handles.add(handle)
        fact_builder.add_rate(
            self.facts, handle=handle, rate_hz=recorder.round_rate(hz),
            expression=joined_text(tokens), location=location)

    def _rate_sleep(self, arguments, ctx):
        i = self._current['index']
        handle = self._object_handle(self._current['object'])

        def continue_before(loop):
            return any(t.text == 'continue'
                       for t in self.tokens[loop.body_start:i])
        found = recorder.paced_loop(
            ctx, continue_before=continue_before,
            made_in_loop=lambda loop: False)
        if found is None:
            return
        loop_id, loop = found
        if any(p.loop == loop_id for p in self.facts.paced_loops):
            return
        recorder.record_paced_loop(
            self.facts, ctx, loop_id=loop_id, clock=handle,
            loop_location=self._location(loop.body_start),
            sleep_location=self._location(i))
