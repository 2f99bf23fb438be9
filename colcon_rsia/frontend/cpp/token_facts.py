# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Facts from a unit's tokens where its AST lost them.

A call clang could not resolve (its object's type unknown, a member or an
overload the model lacks, an error earlier in the statement) is dropped
from the AST or left without the declaration it calls. Its tokens stay,
and so does the extent of the function around it. After the walk, every
function body of the package that the unit defines is read again as
tokens (:func:`recover_facts`): a call the AST did not resolve whose name
says what it does (``ros_api.METHODS_BY_NAME``: ``advertise``,
``create_publisher``, ``publish``... or a qualified name of the API table)
becomes the fact the AST would have made, from what the tokens show: the
name argument, the message type (the explicit template argument, or the
callback's parameter), the callback (``&C::m``, ``std::bind``, a lambda, a
function), the member or variable the result is stored in, the loops and
branches around it. A call of one of the unit's own functions by name
becomes a call edge. Facts made here say ``origin='tokens'``; where the AST
has a call, its facts win and the tokens add nothing.
"""

from dataclasses import dataclass
import re

import clang.cindex as ci
from colcon_rsia.frontend import fact_builder
from colcon_rsia.frontend import recorder
from colcon_rsia.frontend import ros_api
from colcon_rsia.frontend.cpp.cursors import all_base_class_names
from colcon_rsia.frontend.cpp.cursors import CLASS_KINDS
from colcon_rsia.frontend.cpp.cursors import FUNCTION_KINDS
from colcon_rsia.frontend.cpp.cursors import walk_preorder
from colcon_rsia.frontend.cpp.token_roles import CallFacts
from colcon_rsia.frontend.cpp.token_text import brackets
from colcon_rsia.frontend.cpp.token_text import CLOSING
from colcon_rsia.frontend.cpp.token_text import joined_text
from colcon_rsia.frontend.cpp.token_text import OPENING
from colcon_rsia.frontend.cpp.token_text import seconds_of
from colcon_rsia.frontend.cpp.token_text import string_literal
from colcon_rsia.frontend.cpp.token_text import tokens_of
from colcon_rsia.summary.kinds import ORIGIN_TOKENS

CK = ci.CursorKind
TOKENS = ORIGIN_TOKENS

# tokens after which a `[` starts a lambda, not a subscript
_BEFORE_LAMBDA = frozenset({
    '(', ',', '=', '{', '}', ';', 'return', '?', ':', '&&', '||', '!'})
_BIND = frozenset({'bind'})


@dataclass
class _Function:
    """A body being read: its id, file, class and named declarations."""

    id: str
    file: str          # as libclang names it
    relative: str      # relative to the package
    owner: object      # the class cursor of a method, else None
    locals: dict       # spelling -> VAR_DECL/PARM_DECL cursor


@dataclass
class _Loop:
    """Stands for a loop's syntax node in a recorder.Context."""

    body_start: int
    body_end: int


def recover_facts(tu, facts, *, definitions, relpath, ros2, resolved_calls,
                  classes=None):
    """Add the facts the tokens of the unit's function bodies show.

    Only bodies the parse may have lost something of are read: those with
    an error inside, or whose body the AST has empty while the source is
    not (a declaration clang rejected drops its body); after a fatal error
    (a missing include) clang reports nothing more, and every body is
    read. A clean unit costs nothing here.

    :param tu: the parsed unit
    :param facts: the unit's TuFacts, from the AST walk
    :param definitions: {function id: definition cursor} of the package's
      functions the walk met
    :param relpath: the path of a file relative to the package
    :param ros2: whether the unit uses rclcpp (a method name's API)
    :param resolved_calls: {file: {end offset: start offset}}: the calls
      the AST resolved, by their extents
    :param classes: {class name: [definition cursor]} of the package's
      classes, whose constructors a declaration may run
    """
    errors = {}
    fatal = False
    for diagnostic in tu.diagnostics:
        location = diagnostic.location
        fatal = fatal or diagnostic.severity >= ci.Diagnostic.Fatal
        if diagnostic.severity >= ci.Diagnostic.Error and location.file:
            errors.setdefault(location.file.name, []).append(location.offset)
    reader = _Reader(tu, facts, relpath=relpath, ros2=ros2,
                     resolved_calls=resolved_calls, definitions=definitions,
                     classes=classes or {})
    for function_id, cursor in list(definitions.items()):
        if fatal or _may_have_lost(cursor, errors):
            reader.function(function_id, cursor)
    # a function registered as a callback is a root of its own, not
    # something the function naming it calls (the AST may have seen the
    # name alone, in a call it could not resolve)
    facts.calls = [c for c in facts.calls if not (
        c.kind == 'ref' and c.callee in reader.registered)]


def _may_have_lost(cursor, errors):
    """Whether the AST may lack calls of a function definition."""
    extent = cursor.extent
    if extent.start.file is None:
        return False
    start, end = extent.start.offset, extent.end.offset
    if any(start <= offset <= end
           for offset in errors.get(extent.start.file.name, ())):
        return True
    body = next((c for c in cursor.get_children()
                 if c.kind == CK.COMPOUND_STMT), None)
    # a body left empty although its braces hold more than blanks
    return body is not None and next(body.get_children(), None) is None and \
        body.extent.end.offset - body.extent.start.offset > 2 and \
        len(list(body.get_tokens())) > 2


class _Reader(CallFacts):
    """Reads function bodies as tokens; see :func:`recover_facts`."""

    def __init__(  # noqa: D107
            self, tu, facts, *, relpath, ros2, resolved_calls, definitions,
            classes):
        self.tu = tu
        self.definitions = definitions
        self.classes = classes
        self.facts = facts
        self.relpath = relpath
        self.ros2 = ros2
        self.resolved_calls = resolved_calls
        self.known_functions = {f.id for f in facts.functions}
        # qualified name -> ids, short name -> functions of the unit
        self.by_name = {}
        self.by_short_name = {}
        for function in facts.functions:
            self.by_name.setdefault(function.name, []).append(function.id)
            short = function.name.rsplit('::', 1)[-1]
            self.by_short_name.setdefault(short, []).append(function)
        self.rate_handles = {r.handle for r in facts.rates}
        self.recorded = {
            role: {f.location for f in found} for role, found in (
                ('publisher', facts.publishers),
                ('subscriber', facts.subscribers),
                ('timer', facts.timers), ('service', facts.services),
                ('publish', facts.publish_sites), ('rate', facts.rates))}
        # (function id, lambda token offset) of lambdas passed as callbacks
        self.consumed = set()
        # the function ids registered as callbacks
        self.registered = set()
        self.tokens = []
        self.pairs = {}
        self.function_ = None
        # the call being read: index, start, object, template, api, name
        self._current = {}

    # --- one function ------------------------------------------------------

    def function(self, function_id, cursor):
        body = next((c for c in cursor.get_children()
                     if c.kind == CK.COMPOUND_STMT), None)
        if body is None or cursor.location.file is None:
            return
        tokens = tokens_of(self.tu, cursor.extent)
        start = next((i for i, t in enumerate(tokens)
                      if t.offset == body.extent.start.offset), None)
        if start is None:
            return  # a body made by a macro: no tokens of its own here
        self.tokens = tokens
        self.pairs = brackets(tokens)
        parent = cursor.semantic_parent
        locals_ = {}
        for current in walk_preorder(cursor):
            if current.kind in (CK.VAR_DECL, CK.PARM_DECL) and \
                    current.spelling:
                locals_.setdefault(current.spelling, current)
        self.function_ = _Function(
            id=function_id, file=cursor.location.file.name,
            relative=self.relpath(cursor.location.file.name),
            owner=parent if parent is not None and
            parent.kind in CLASS_KINDS else None, locals=locals_)
        ctx = recorder.Context(function_id, owner=self.function_.owner)
        if cursor.kind == CK.CONSTRUCTOR:
            self._initializers(cursor, start, ctx)
        end = self.pairs.get(start)
        if end is not None:
            self._scan(start + 1, end, ctx)

    def _initializers(self, cursor, body_start, ctx):
        """``: Node("talker"), pub_(nh.advertise<M>("out", 1))``."""
        tokens = self.tokens
        # the name its parameters follow: out of its class, the class's
        # name qualifies it first (`Mapper::Mapper(`)
        name = next((i for i, t in enumerate(tokens[:body_start - 1])
                     if t.text == cursor.spelling and
                     tokens[i + 1].text == '('), None)
        if name is None:
            return
        i = self.pairs.get(name + 1, body_start) + 1
        while i < body_start and tokens[i].text != ':':
            i += 1
        i += 1
        while i < body_start:
            if tokens[i].kind == 'IDENTIFIER' and i + 1 < body_start and \
                    tokens[i + 1].text in ('(', '{'):
                closing = self.pairs.get(i + 1, body_start)
                self._base_initializer(i, closing, ctx)
                self._scan(i + 2, closing, ctx, target=(i, tokens[i].text))
                i = closing + 1
            else:
                i += 1

    def _base_initializer(self, i, closing, ctx):
        """``: Node("talker")``: a base class that names the node."""
        name = self.tokens[i].text
        qualifier = self._qualifier(i)
        candidates = [f'{qualifier}::{name}::{name}'] if qualifier else [
            c for c in ros_api.methods_named(name)
            if c.endswith(f'::{name}::{name}')]
        for candidate in candidates:
            api = ros_api.lookup_call(candidate)
            if api is not None and api.role == ros_api.NODE_NAME:
                self._current = dict(
                    index=i, start=i, object=None, template=None, api=api,
                    name=candidate, target=None)
                self._node_name(self._arguments(i + 1, closing), ctx)
                return

    # --- statements ----------------------------------------------------------

    def _statement_end(self, i, end):
        """Index of the last token of the statement starting at `i`."""
        tokens = self.tokens
        if i >= end:
            return end - 1
        text = tokens[i].text
        if text == '{':
            return self.pairs.get(i, end - 1)
        if text in ('while', 'for', 'switch') and i + 1 < end and \
                tokens[i + 1].text == '(':
            return self._statement_end(self.pairs.get(i + 1, end) + 1, end)
        if text == 'if':
            j = i + 1
            if j < end and tokens[j].text == 'constexpr':
                j += 1
            if j < end and tokens[j].text == '(':
                last = self._statement_end(self.pairs.get(j, end) + 1, end)
                if last + 1 < end and tokens[last + 1].text == 'else':
                    return self._statement_end(last + 2, end)
                return last
        if text == 'do':
            last = self._statement_end(i + 1, end)
            j = last + 1
            if j < end and tokens[j].text == 'while' and j + 1 < end:
                j = self.pairs.get(j + 1, end - 1) + 1
            return min(j, end - 1)
        j = i
        while j < end and tokens[j].text != ';':
            j = self.pairs.get(j, j) + 1 if tokens[j].text in OPENING \
                else j + 1
        return min(j, end - 1)

    def _scan(self, start, end, ctx, target=None):
        """Read tokens[start:end] as statements and expressions."""
        tokens = self.tokens
        i = start
        while i < end:
            token = tokens[i]
            text = token.text
            if token.kind == 'KEYWORD' and text in ('while', 'for') and \
                    i + 1 < end and tokens[i + 1].text == '(':
                i = self._loop(i, end, ctx)
            elif token.kind == 'KEYWORD' and text == 'do':
                i = self._do_loop(i, end, ctx)
            elif token.kind == 'KEYWORD' and text in ('if', 'switch'):
                i = self._branching(i, end, ctx)
            elif token.kind == 'KEYWORD' and text == 'catch':
                j = i + 1
                if j < end and tokens[j].text == '(':
                    j = self.pairs.get(j, end) + 1
                last = self._statement_end(j, end)
                with ctx.branch():
                    self._scan(j, last + 1, ctx)
                i = last + 1
            elif text == '[' and (i == start or tokens[i - 1].text in
                                  _BEFORE_LAMBDA) and i in self.pairs:
                i = self._lambda(i, end, ctx)
            elif token.kind == 'IDENTIFIER':
                i = self._identifier(i, end, ctx, target)
            else:
                i += 1

    def _loop(self, i, end, ctx):
        tokens = self.tokens
        closing = self.pairs.get(i + 1, end - 1)
        last = self._statement_end(closing + 1, end)
        loop_id = f'{self.function_.relative}@{tokens[i].offset}'
        with ctx.loop(loop_id, _Loop(closing + 1, last)):
            self._scan(i + 2, closing, ctx)
            self._scan(closing + 1, last + 1, ctx)
        return last + 1

    def _do_loop(self, i, end, ctx):
        tokens = self.tokens
        last = self._statement_end(i + 1, end)
        loop_id = f'{self.function_.relative}@{tokens[i].offset}'
        condition_end = last
        if last + 2 < end and tokens[last + 1].text == 'while':
            condition_end = self.pairs.get(last + 2, last)
        with ctx.loop(loop_id, _Loop(i + 1, last)):
            self._scan(i + 1, last + 1, ctx)
            self._scan(last + 1, condition_end + 1, ctx)
        return condition_end + 1

    def _branching(self, i, end, ctx):
        tokens = self.tokens
        j = i + 1
        if j < end and tokens[j].text == 'constexpr':
            j += 1
        if j >= end or tokens[j].text != '(':
            return i + 1
        closing = self.pairs.get(j, end - 1)
        self._scan(j + 1, closing, ctx)
        last = self._statement_end(closing + 1, end)
        with ctx.branch():
            self._scan(closing + 1, last + 1, ctx)
        if tokens[i].text == 'if' and last + 1 < end and \
                tokens[last + 1].text == 'else':
            other = self._statement_end(last + 2, end)
            with ctx.branch():
                self._scan(last + 2, other + 1, ctx)
            last = other
        return last + 1

    def _lambda(self, i, end, ctx):
        """A lambda: a function of its own, referenced where it is made."""
        tokens = self.tokens
        j = self.pairs[i] + 1
        if j < end and tokens[j].text == '(':
            j = self.pairs.get(j, end) + 1
        while j < end and tokens[j].text not in ('{', ';', ')', ','):
            j += 1
        if j >= end or tokens[j].text != '{' or j not in self.pairs:
            return i + 1
        body_end = self.pairs[j]
        lambda_id = self._lambda_id(i)
        if lambda_id not in self.known_functions:
            self.known_functions.add(lambda_id)
            fact_builder.add_function(
                self.facts, id=lambda_id,
                name=f'lambda@{self.function_.relative}:{tokens[i].line}',
                location=self._location(i), class_id=None)
            if (ctx.function, tokens[i].offset) not in self.consumed:
                self._call_edge(ctx, lambda_id, i, kind='ref')
        self._scan(j + 1, body_end, recorder.Context(
            lambda_id, owner=ctx.owner))
        return body_end + 1

    def _lambda_id(self, i):
        token = self.tokens[i]
        return f'lambda@{self.function_.relative}:{token.line}:{token.column}'

    def _location(self, i):
        return f'{self.function_.relative}:{self.tokens[i].line}'

    # --- calls -------------------------------------------------------------

    def _identifier(self, i, end, ctx, target):
        """An identifier: a call, a declaration made by a call, or nothing."""
        tokens = self.tokens
        j = i + 1
        template = None
        if j < end and tokens[j].text == '<':
            closing = self._angle_end(j, end)
            if closing is None:
                return i + 1
            template = (j + 1, closing)
            j = closing + 1
        if j >= end or tokens[j].text not in ('(', '{') or \
                j not in self.pairs:
            return i + 1
        closing = self.pairs[j]
        if tokens[j].text == '(' or self._declares(i):
            self._call(i, j, closing, template, ctx, target)
        # what the arguments hold is read in the call's context
        self._scan(j + 1, closing, ctx)
        return closing + 1

    def _angle_end(self, j, end):
        """The `>` closing a template argument list at `j`, or None."""
        depth = 0
        i = j
        while i < end:
            text = self.tokens[i].text
            if text == '<':
                depth += 1
            elif text == '>':
                depth -= 1
            elif text == '>>':
                depth -= 2
            elif text in (';', '{', '}', '&&', '||'):
                return None
            elif text in OPENING:
                i = self.pairs.get(i, i)
            elif text in CLOSING:
                return None
            if depth <= 0:
                return i if depth == 0 else None
            i += 1
        return None

    def _declares(self, i):
        """Whether the identifier at `i` is a variable being declared."""
        if i == 0:
            return False
        before = self.tokens[i - 1]
        return before.kind == 'IDENTIFIER' or before.text in ('>', '*', '&') \
            and i >= 2 and self.tokens[i - 2].kind in ('IDENTIFIER', 'KEYWORD')

    def _object(self, i):
        """(start, end) of the object expression of a member call at `i`."""
        tokens = self.tokens
        if i < 2 or tokens[i - 1].text not in ('.', '->'):
            return None
        j = i - 2
        while j >= 0:
            text = tokens[j].text
            if text in (')', ']') and j in self.pairs:
                j = self.pairs[j] - 1
                continue
            if tokens[j].kind == 'IDENTIFIER' or text == 'this':
                if j >= 1 and tokens[j - 1].text in ('.', '->', '::'):
                    j -= 2
                    continue
                return j, i - 1
            return (j + 1, i - 1) if j + 1 < i - 1 else None
        return (0, i - 1) if i > 1 else None

    def _qualifier(self, i):
        """``ns::Class`` before ``::name`` at `i`, as text, or ''."""
        tokens = self.tokens
        parts = []
        j = i - 1
        while j >= 1 and tokens[j].text == '::' and \
                tokens[j - 1].kind == 'IDENTIFIER':
            parts.insert(0, tokens[j - 1].text)
            j -= 2
        return '::'.join(parts)

    def _resolved(self, i, closing):
        """Whether the AST resolved the call named at `i`, ending at `closing`.

        The AST's call ends where its `)` does, and starts at or before
        its name (at its object).
        """
        start = self.resolved_calls.get(self.function_.file, {}).get(
            self.tokens[closing].offset + 1)
        return start is not None and start <= self.tokens[i].offset

    def _call(self, i, opening, closing, template, ctx, target):
        tokens = self.tokens
        name = tokens[i].text
        if self._resolved(i, closing):
            return
        qualifier = self._qualifier(i)
        object_range = self._object(i)
        start = object_range[0] if object_range else \
            i - 2 * len(qualifier.split('::')) if qualifier else i
        arguments = self._arguments(opening, closing)
        if self._declares(i):
            # `ros::Rate r(10);`: a variable made, not a call by its name;
            # `Node node(options);` runs a constructor of the package
            if self._rate_type(i):
                self._rate(i, arguments, ctx)
            else:
                for constructor in self._constructors(self._type_before(
                        self._type_end(i))):
                    self._call_edge(ctx, constructor, self._type_end(i))
            return
        if name in ros_api.FORWARDING_FACTORY_NAMES and template is not None:
            # make_shared<C>(...): C's constructor
            made = joined_text(tokens[template[0]:template[1]]).split('<')[0]
            for constructor in self._constructors(made):
                self._call_edge(ctx, constructor, start)
            return
        api_name = self._api(name, qualifier, object_range, len(arguments))
        if api_name == ros_api.QT_CONNECT and 'QTimer::timeout' not in \
                joined_text(tokens[opening:closing]).replace(' ', ''):
            api_name = None  # a `connect` of the package's own, maybe
        if api_name is None:
            if i > 0 and tokens[i - 1].text == 'new':
                for constructor in self._constructors(
                        f'{qualifier}::{name}' if qualifier else name):
                    self._call_edge(ctx, constructor, start)
            elif tokens[opening].text == '(':
                self._package_call(i, start, object_range, qualifier, ctx)
            return
        api = ros_api.lookup_call(api_name)
        handler = {
            ros_api.PUBLISHER: self._publisher,
            ros_api.SUBSCRIBER: self._subscriber,
            ros_api.TIMER: self._timer,
            ros_api.SERVICE: self._service,
            ros_api.PUBLISH: self._publish,
            ros_api.RATE_SLEEP: self._rate_sleep,
            ros_api.NODE_NAME: self._node_name,
            ros_api.RATE: self._rate,
            ros_api.SIGNAL_CONNECT: self._signal_connect,
        }.get(api.role)
        if handler is None:
            return
        self._current = dict(
            index=i, start=start, object=object_range, template=template,
            api=api, name=api_name, target=target)
        handler(i, arguments, ctx) if api.role == ros_api.RATE else \
            handler(arguments, ctx)

    def _api(self, name, qualifier, object_range, arguments):
        """The qualified API a token call stands for, or None."""
        if qualifier:
            for candidate in (f'{qualifier}::{name}',
                              f'{qualifier}::{name}::{name}'):
                if ros_api.lookup_call(candidate) is not None:
                    return candidate
            if qualifier not in ('this', 'std', 'boost'):
                # a base class's method (`Node::create_publisher`)
                return self._api_by_name(name, arguments)
            return None
        if name == 'sleep':
            handle = self._object_handle(object_range)
            return (ros_api.RATE_SLEEP_BY_NAME[1] if self.ros2 else
                    ros_api.RATE_SLEEP_BY_NAME[0]) \
                if handle in self.rate_handles else None
        if not object_range:
            # a call on the object itself: a method of its class's bases
            # (`advertise<M>(*pnh_, "out", 1)` of a lazy nodelet base is
            # no NodeHandle's `advertise("out", 1)`)
            return self._api_of_bases(name) or \
                self._api_by_name(name, arguments)
        return self._api_of_object_type(name, object_range) or \
            self._api_by_name(name, arguments)

    def _api_of_bases(self, name):
        """The API of a method of the bases of the function's class."""
        owner = self.function_.owner if self.function_ else None
        if owner is None:
            return None
        bases = all_base_class_names(owner)
        # (a base the parse could not declare has the name it is written
        # with, which may leave out its namespace)
        short_bases = {base.rsplit('::', 1)[-1] for base in bases}
        for candidate in ros_api.methods_named(name):
            owner_class = candidate.rsplit('::', 1)[0]
            if owner_class in bases or \
                    owner_class.rsplit('::', 1)[-1] in short_bases:
                return candidate
        return None

    def _api_by_name(self, name, arguments):
        """The API of a method name, of the unit's ROS version first."""
        return ros_api.dependent_method(
            name, ros2=self.ros2, arguments=arguments) or \
            ros_api.dependent_method(
                name, ros2=not self.ros2, arguments=arguments)

    def _api_of_object_type(self, name, object_range):
        """The API of the class the object's declaration names."""
        declaration = self._object_declaration(object_range)
        if declaration is None:
            return None
        written = joined_text(tokens_of(self.tu, declaration.extent))
        written = written.split(declaration.spelling)[0] or written
        for candidate in ros_api.methods_named(name):
            owner = candidate.rsplit('::', 2)[-2]
            if re.search(r'\b' + re.escape(owner) + r'\b', written):
                return candidate
        return None

    def _arguments(self, opening, closing):
        """[(start, end)] of the arguments between two brackets."""
        tokens = self.tokens
        ranges = []
        start = opening + 1
        i = start
        while i < closing:
            text = tokens[i].text
            if text in OPENING:
                i = self.pairs.get(i, i) + 1
                continue
            if text == '<' and i > 0 and tokens[i - 1].kind == 'IDENTIFIER':
                angle = self._angle_end(i, closing)
                if angle is not None:
                    i = angle + 1
                    continue
            if text == ',':
                ranges.append((start, i))
                start = i + 1
            i += 1
        if start < closing:
            ranges.append((start, closing))
        return ranges

    def _argument(self, arguments, position):
        """(start, end) of an argument by its ros_api position, or None."""
        tokens = self.tokens
        if position == ros_api.FIRST_STRING:
            return next((a for a in arguments if any(
                t.kind == 'LITERAL' and '"' in t.text
                for t in tokens[a[0]:a[1]])), None)
        if position == ros_api.FIRST_CALLABLE:
            return next((a for a in arguments if self._looks_callable(a)),
                        None)
        if position == ros_api.FIRST_DURATION:
            return next((a for a in arguments
                         if seconds_of(tokens[a[0]:a[1]]) is not None), None)
        if isinstance(position, int) and position < len(arguments):
            return arguments[position]
        return None

    def _looks_callable(self, argument):
        texts = [t.text for t in self.tokens[argument[0]:argument[1]]]
        return bool(texts) and (texts[0] in ('&', '[') or 'bind' in texts)

    # --- what the arguments say -------------------------------------------

    def _topic(self, argument):
        """(topic as written, is it a literal, handle of its variable)."""
        if argument is None:
            return None, False, None
        start, end = argument
        while end - start > 2 and self.tokens[start].text == '(' and \
                self.pairs.get(start) == end - 1:
            start, end = start + 1, end - 1  # ("name"): the name
        tokens = self.tokens[start:end]
        literal = string_literal(tokens)
        if literal is not None:
            return literal, True, None
        names = [t for t in tokens if t.kind == 'IDENTIFIER']
        handle = None
        if len(names) == 1 and all(
                t.kind == 'IDENTIFIER' or t.text in ('this', '->', '.')
                for t in tokens):
            handle = self._handle(names[0].text)[0]
        return (joined_text(tokens) or None), False, handle

    def _callback(self, argument, ctx):
        """(function id, declaration cursor) of a callback argument."""
        callback, declaration = self._callable(argument, ctx)
        if callback is not None:
            self.registered.add(callback)
        return callback, declaration

    def _callable(self, argument, ctx):
        if argument is None:
            return None, None
        tokens = self.tokens
        start, end = argument
        if start < end and tokens[start].text == '[':
            self.consumed.add((ctx.function, tokens[start].offset))
            return self._lambda_id(start), None
        texts = [t.text for t in tokens[start:end]]
        if 'bind' in texts:
            bind = texts.index('bind')
            opening = start + bind + 1
            if opening < end and tokens[opening].text == '(' and \
                    opening in self.pairs:
                inner = self._arguments(opening, self.pairs[opening])
                if inner:
                    return self._callable(inner[0], ctx)
            return None, None
        names = [(t.text, k) for k, t in enumerate(tokens[start:end])
                 if t.kind == 'IDENTIFIER']
        if not names or any(t.text not in ('&', '::') and
                            t.kind != 'IDENTIFIER'
                            for t in tokens[start:end]):
            return None, None
        qualified = ''.join(texts).lstrip('&')
        return self._function_named(qualified)

    def _function_named(self, qualified):
        """(id, declaration) of the unit's function a name designates."""
        short = qualified.rsplit('::', 1)[-1]
        matches = [f for f in self.by_short_name.get(short, ())
                   if f.name == qualified or
                   f.name.endswith('::' + qualified)]
        if len(matches) == 1:
            return matches[0].id, self._declaration_of(matches[0].id, short)
        # declared in a class here, defined in another unit
        owner = self.function_.owner
        scope = qualified.rsplit('::', 1)[0] if '::' in qualified else None
        if owner is not None and (scope is None or scope == owner.spelling):
            for child in owner.get_children():
                if child.kind in FUNCTION_KINDS and child.spelling == short:
                    return child.get_usr(), child
        return None, None

    def _constructors(self, class_name):
        """The ids of the package's constructors of a class.

        Those the unit defines, and those the class declares (defined in
        another unit: the same ids).
        """
        short = class_name.rsplit('::', 1)[-1]
        found = [f.id for f in self.by_short_name.get(short, ())
                 if f.name.endswith(f'{class_name}::{short}')]
        for definition in self.classes.get(short, ()):
            found += [child.get_usr() for child in definition.get_children()
                      if child.kind == CK.CONSTRUCTOR]
        return list(dict.fromkeys(found))

    def _type_end(self, i):
        """The last token of the type a declaration at `i` declares."""
        j = i - 1
        while j > 0 and self.tokens[j].text in ('*', '&', '&&'):
            j -= 1
        return j

    def _declaration_of(self, function_id, short):
        if function_id in self.definitions:
            return self.definitions[function_id]
        owner = self.function_.owner
        if owner is not None:
            for child in owner.get_children():
                if child.kind in FUNCTION_KINDS and \
                        child.get_usr() == function_id:
                    return child
        return None

    def _handle(self, name):
        """(id, cursor) of the variable or member a name designates.

        A local or parameter of the function, else a member of its class,
        else a name of the function (or class) the tokens alone know.
        """
        function = self.function_
        if name in function.locals:
            cursor = function.locals[name]
            return cursor.get_usr(), cursor
        owner = function.owner
        if owner is not None:
            for child in owner.get_children():
                if child.kind in (CK.FIELD_DECL, CK.VAR_DECL) and \
                        child.spelling == name:
                    return child.get_usr(), child
            return f'{TOKENS}:{owner.get_usr()}:{name}', None
        return f'{TOKENS}:{function.id}:{name}', None

    def _object_handle(self, object_range):
        declaration_id, _ = self._object_name(object_range)
        return declaration_id

    def _object_name(self, object_range):
        """(handle id, cursor) of the last name of an object expression."""
        if object_range is None:
            return None, None
        names = [t for t in self.tokens[object_range[0]:object_range[1]]
                 if t.kind == 'IDENTIFIER']
        if not names:
            return None, None
        return self._handle(names[-1].text)

    def _object_declaration(self, object_range):
        return self._object_name(object_range)[1]

    def _package_call(self, i, start, object_range, qualifier, ctx):
        """A call of one of the unit's functions, by its name."""
        name = self.tokens[i].text
        callee = None
        if object_range is None or all(
                t.text in ('this', '->') for t in
                self.tokens[object_range[0]:object_range[1]]):
            callee, _ = self._function_named(
                f'{qualifier}::{name}' if qualifier else name)
        else:
            methods = [f for f in self.by_short_name.get(name, ())
                       if f.class_id is not None]
            if len(methods) == 1:
                callee = methods[0].id
        if callee is not None and callee != ctx.function:
            self._call_edge(ctx, callee, start)

    def _call_edge(self, ctx, callee, i, kind='call'):
        location = self._location(i)
        if any(c.caller == ctx.function and c.callee == callee and
               c.location == location for c in self.facts.calls):
            return
        fact_builder.add_call(
            self.facts, caller=ctx.function, callee=callee, location=location,
            loops=ctx.loop_ids(), kind=kind)
