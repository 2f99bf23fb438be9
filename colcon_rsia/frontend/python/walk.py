# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The walk of a Python module's function bodies to its facts.

Part of the Python front end (see :mod:`colcon_rsia.frontend.python`).
"""

import ast
import os

from colcon_rsia.frontend import fact_builder
from colcon_rsia.frontend import python_api
from colcon_rsia.frontend import recorder
from colcon_rsia.frontend import ros_api
from colcon_rsia.frontend.python.helpers import Helpers
from colcon_rsia.frontend.python.params import Params
from colcon_rsia.frontend.python.roles import Roles
from colcon_rsia.frontend.python.scopes import FUNCTION_NODES
from colcon_rsia.frontend.python.scopes import lookup
from colcon_rsia.frontend.python.scopes import MODULE_FUNCTION
from colcon_rsia.frontend.python.scopes import own_children
from colcon_rsia.frontend.python.scopes import SourceError
from colcon_rsia.frontend.python.values import BOUND
from colcon_rsia.frontend.python.values import call_argument
from colcon_rsia.frontend.python.values import CLASS
from colcon_rsia.frontend.python.values import EXT
from colcon_rsia.frontend.python.values import EXTBOUND
from colcon_rsia.frontend.python.values import FUNC
from colcon_rsia.frontend.python.values import PARTIAL
from colcon_rsia.frontend.python.values import Project
from colcon_rsia.frontend.python.values import STUB

COMPREHENSIONS = (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)
TRY_NODES = tuple(t for t in (ast.Try, getattr(ast, 'TryStar', None)) if t)
# method calls that store their argument in the object they are called on
CONTAINER_ADDERS = frozenset({
    'append', 'appendleft', 'extend', 'add', 'insert', 'setdefault',
    '__setitem__'})
# expressions a created object passes through on its way to a variable
PASS_THROUGH = (ast.Set, ast.Dict, ast.Starred, ast.IfExp, ast.Await,
                ast.BoolOp) + COMPREHENSIONS


def normalize_msg_type(dotted):
    """``std_msgs.msg.String`` -> ``std_msgs::String``."""
    if not dotted:
        return None
    parts = [p for p in dotted.replace(' ', '').split('.') if p]
    if len(parts) >= 3 and parts[1] in ('msg', 'srv', 'action'):
        return f'{parts[0]}::{parts[-1]}'
    return '::'.join(parts) or None


def extract_python_facts(path, *, package_path, module_name,
                         package_modules):
    """Read one Python module and return its facts.

    :param str path: the module's file
    :param str package_path: absolute path of the package source
    :param str module_name: the module's dotted name (a script: its file
      name without ``.py``)
    :param dict package_modules: {dotted name: file} of every Python module
      of the package, for imports between them
    :rtype: colcon_rsia.frontend.facts.TuFacts
    """
    package_path = os.path.abspath(package_path)
    relpath = os.path.relpath(os.path.abspath(path), package_path)
    facts = fact_builder.unit_facts(relpath, files=[relpath])
    modules = dict(package_modules)
    modules[module_name] = path
    project = Project(package_path, modules)
    try:
        module = project.load(module_name)
    except SourceError as e:
        facts.diagnostics.append(f'{relpath}: {e}')
        return facts
    try:
        _Extractor(project, module, facts).run()
    except RecursionError:
        return fact_builder.unit_facts(relpath, diagnostics=[
            f'{relpath}: too deeply nested to analyse'])
    return facts


class _Extractor(Roles, Params, Helpers):
    """Collects the facts of one module; see :func:`extract_python_facts`."""

    def __init__(self, project, module, facts):
        self.project = project
        self.module = module
        self.facts = facts
        self.relpath = module.relpath
        # expressions used as a registered callback: not a plain reference
        self._consumed = set()
        self._registered = set()
        self._lambdas_in_variables = set()
        self._stubs = set()
        # function id -> the endpoint calls a helper may make (helpers.py)
        self._endpoint_site_cache = {}

    def run(self):
        for scope in self.module.functions:
            self._function(scope)
        self._dispatch_edges()
        # a lambda stored in a variable and registered as a callback is a
        # root, not something its defining function calls
        self.facts.calls = [
            c for c in self.facts.calls
            if not (c.kind == 'ref' and c.callee in self._registered and
                    c.callee in self._lambdas_in_variables)]

    # --- locations ------------------------------------------------------

    def location(self, node):
        return f'{self.relpath}:{getattr(node, "lineno", 1)}'

    def loop_id(self, node):
        return f'{self.relpath}@{node.lineno}:{node.col_offset}'

    def synthetic(self, node):
        return f'new@{self.relpath}:{node.lineno}:{node.col_offset}'

    def text(self, node):
        if hasattr(ast, 'unparse'):
            return ast.unparse(node)
        segment = ast.get_source_segment(self.module.text, node) or ''
        return ' '.join(segment.split())

    # --- functions ------------------------------------------------------

    def _function(self, scope):
        if scope.kind == 'module':
            name, location, class_id = MODULE_FUNCTION, f'{self.relpath}:1', \
                None
        elif scope.kind == 'lambda':
            location = self.location(scope.node)
            name, class_id = f'lambda@{location}', None
        else:
            location = self.location(scope.node)
            name = scope.qualname
            class_id = scope.cls.id if scope.cls is not None else None
        fact_builder.add_function(
            self.facts, id=scope.id, name=name, location=location, class_id=class_id,
            params=[scope.handle(p) for p in scope.params])
        context = recorder.Context(scope.id, scope=scope)
        body = [scope.node.body] if scope.kind == 'lambda' \
            else scope.node.body
        for node in body:
            try:
                self._visit(node, context)
            except RecursionError:
                # an expression nested deeper than Python's stack (a sum
                # of a thousand terms): that statement's facts are lost,
                # not the module's
                self.facts.diagnostics.append(
                    f'{self.location(node)}: nested too deeply to analyse; '
                    'this statement is skipped')

    def _stub(self, value):
        cls, name = value.ref
        stub_id = f'{cls.id}.{name}'
        if stub_id not in self._stubs:
            self._stubs.add(stub_id)
            fact_builder.add_function(
                self.facts, id=stub_id, name=f'{cls.qualname}.{name}',
                location=cls.location, class_id=cls.id)
        return stub_id

    def _dispatch_edges(self):
        """``Base.m`` may run ``Sub.m``: an edge from each base's method."""
        for cls in self.module.classes:
            bases = self.project.mro(cls)[0][1:]
            for name, method in cls.methods.items():
                if name.startswith('__') and name.endswith('__'):
                    continue
                for base in bases:
                    fact_builder.add_call(
                        self.facts, caller=f'{base.id}.{name}', callee=method.id,
                        location=self.location(method.node))

    def _add_call(self, context, callee, node, kind='call'):
        fact_builder.add_call(
            self.facts, caller=context.function, callee=callee,
            location=self.location(node), loops=context.loop_ids(),
            kind=kind)

    # --- statements and expressions ---------------------------------------

    def _visit(self, node, context):
        handler = _HANDLERS.get(type(node))
        if handler is not None:
            handler(self, node, context)
        else:
            for child in ast.iter_child_nodes(node):
                self._visit(child, context)

    def _visit_all(self, nodes, context):
        for node in nodes:
            self._visit(node, context)

    def _conditional(self, nodes, context):
        with context.branch():
            self._visit_all(nodes, context)

    def _visit_def(self, node, context):
        # the body is a function of its own; decorators and defaults run here
        self._visit_all(own_children(node), context)

    def _visit_lambda(self, node, context):
        self._visit_all(own_children(node), context)
        lambda_id = self.module.scopes[id(node)].id
        parent = self.module.parents.get(id(node))
        if isinstance(parent, (ast.Assign, ast.AnnAssign, ast.NamedExpr)):
            self._lambdas_in_variables.add(lambda_id)
        if id(node) not in self._consumed:
            self._add_call(context, lambda_id, node, kind='ref')

    def _visit_class(self, node, context):
        self._visit_all(own_children(node), context)
        inner = recorder.Context(
            context.function, scope=self.module.scopes[id(node)],
            loops=context.loops, conditional=context.conditional)
        self._visit_all(node.body, inner)

    def _visit_while(self, node, context):
        self._visit(node.test, context)
        self._loop(node, node.body, context)
        self._visit_all(node.orelse, context)

    def _visit_for(self, node, context):
        self._visit(node.iter, context)
        self._loop(node, [node.target] + node.body, context)
        self._visit_all(node.orelse, context)

    def _loop(self, node, body, context):
        with context.loop(self.loop_id(node), node):
            self._visit_all(body, context)

    def _visit_if(self, node, context):
        self._visit(node.test, context)
        self._conditional(node.body + node.orelse, context)

    def _visit_try(self, node, context):
        self._visit_all(node.body, context)
        self._conditional(node.handlers + node.orelse, context)
        self._visit_all(node.finalbody, context)

    def _visit_match(self, node, context):
        self._visit(node.subject, context)
        self._conditional(node.cases, context)

    def _visit_ifexp(self, node, context):
        self._visit(node.test, context)
        self._conditional([node.body, node.orelse], context)

    def _visit_boolop(self, node, context):
        self._visit(node.values[0], context)
        self._conditional(node.values[1:], context)

    def _visit_comprehension(self, node, context):
        first = node.generators[0]
        self._visit(first.iter, context)
        rest = [first.target] + first.ifs
        for generator in node.generators[1:]:
            rest += [generator.iter, generator.target] + generator.ifs
        if isinstance(node, ast.DictComp):
            rest += [node.key, node.value]
        else:
            rest.append(node.elt)
        self._conditional(rest, context)

    def _visit_call(self, node, context):
        self._call(node, context)
        func = node.func
        if isinstance(func, ast.Attribute):
            self._visit(func.value, context)
        elif not isinstance(func, ast.Name):
            self._visit(func, context)
        self._visit_all(node.args, context)
        self._visit_all([k.value for k in node.keywords], context)

    def _visit_name(self, node, context):
        if isinstance(node.ctx, ast.Load) and id(node) not in self._consumed:
            self._reference(node, context)

    def _visit_attribute(self, node, context):
        if isinstance(node.ctx, ast.Load) and id(node) not in self._consumed:
            self._reference(node, context)
        self._visit(node.value, context)

    def _visit_import(self, node, context):
        """An import runs the imported package modules' bodies."""
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        else:
            base = self.module.import_base(node)
            names = [base] + [f'{base}.{a.name}' for a in node.names
                              if a.name != '*']
        modules = []
        for name in names:
            parts = name.split('.')
            for cut in range(1, len(parts) + 1):
                prefix = '.'.join(parts[:cut])
                if prefix in self.project.package_modules and \
                        prefix != self.module.name and \
                        prefix not in modules:
                    modules.append(prefix)
        for name in modules:
            self._add_call(context, f'{name}:{MODULE_FUNCTION}', node)

    def _reference(self, node, context):
        """A function named but not called here: it may be called later."""
        value = self.project.value(node, context.scope)
        if value is None:
            return
        if value.kind in (FUNC, BOUND):
            self._add_call(context, value.ref.id, node, kind='ref')
        elif value.kind == STUB:
            self._add_call(context, self._stub(value), node, kind='ref')

    # --- calls ------------------------------------------------------------

    def _call(self, node, context):
        called = self.project.value(node.func, context.scope)
        kind = called.kind if called is not None else None
        if kind in (FUNC, BOUND):
            # a method called through its class takes the object first
            offset = 1 if kind == FUNC and called.ref.self_kind == 'obj' \
                else 0
            self._add_call(context, called.ref.id, node)
            self._bind(called.ref, node.args, node.keywords, context, offset)
            self._helper_endpoints(called.ref, node, context, offset)
            return
        if kind == STUB:
            self._add_call(context, self._stub(called), node)
            return
        if kind == CLASS:
            init = self.project.member(called.ref, '__init__', 0, True)
            if init is not None and init.kind in (FUNC, BOUND):
                self._add_call(context, init.ref.id, node)
                self._bind(init.ref, node.args, node.keywords, context, 0)
                self._helper_endpoints(init.ref, node, context, 0)
            return
        name, api = self._api_of(node, called)
        if api is not None:
            handler = _ROLES.get(api.role)
            if handler is not None:
                handler(self, api, name, node, context)

    def _api_of(self, node, called):
        """(name, PyApi) of an API call whose callee evaluates to `called`.

        (None, None) when the call is of no recognised API.
        """
        kind = called.kind if called is not None else None
        name, api = None, None
        if kind in (EXT, EXTBOUND):
            name = called.ref
            api = python_api.lookup(name)
        if api is None and kind in (None, EXTBOUND) and \
                isinstance(node.func, ast.Attribute):
            name = python_api.DUCK_METHODS.get(node.func.attr)
            if name is not None:
                api = python_api.lookup(name) or \
                    python_api.DUCK_CALLS.get(name)
        return (name, api) if api is not None else (None, None)

    def _bind(self, function, args, keywords, context, offset):
        """Record handles passed to a package function's parameters."""
        params = function.params
        for index, argument in enumerate(args):
            if isinstance(argument, ast.Starred):
                break
            position = index - offset
            if position < 0 or position >= len(params):
                continue
            self._bind_one(function, position, argument, context)
        for keyword in keywords:
            if keyword.arg in params:
                self._bind_one(function, params.index(keyword.arg),
                               keyword.value, context)

    def _bind_one(self, function, position, argument, context):
        if isinstance(argument, ast.Constant) and \
                isinstance(argument.value, str):
            fact_builder.add_string_argument(
                self.facts, caller=context.function, callee=function.id, index=position,
                value=argument.value)
            return
        handle = self._object_handle(argument, context)
        if handle is not None:
            fact_builder.add_binding(
                self.facts, callee=function.id, index=position, handle=handle)

    def _object_handle(self, expr, context):
        if isinstance(expr, ast.Call):
            return self.synthetic(expr)
        container = self._iterated(expr)
        if container is not None:
            return self._object_handle(container, context)
        return self.project.handle(expr, context.scope)

    def _iterated(self, expr):
        """The container a loop variable is an element of, or None.

        ``for pub in self.pubs: pub.publish(m)`` publishes through the
        publishers ``self.pubs`` holds; so do ``for name, pub in
        self.pubs.items()`` and ``for i, pub in enumerate(self.pubs)``.
        """
        if not isinstance(expr, ast.Name):
            return None
        parent = self.module.parents.get(id(expr))
        while parent is not None:
            if isinstance(parent, (ast.For, ast.AsyncFor)):
                found = _element_of(parent.target, parent.iter, expr.id)
                if found is not None:
                    return found
            if isinstance(parent, FUNCTION_NODES + (ast.ClassDef,)):
                return None
            parent = self.module.parents.get(id(parent))
        return None

    def _receiver(self, node, context):
        """The handle of the object a method is called on."""
        if isinstance(node.func, ast.Attribute):
            return self._object_handle(node.func.value, context)
        return None

    def _target(self, node, context):
        """Return (handle, name) of where a call's result is stored.

        A synthetic handle when the result is used without a name.
        """
        child = node
        parent = self.module.parents.get(id(node))
        while parent is not None:
            if isinstance(parent, ast.Assign):
                if child is parent.value:
                    return self._target_handle(parent.targets[0], context)
                break
            if isinstance(parent, (ast.AnnAssign, ast.NamedExpr)):
                if child is parent.value:
                    return self._target_handle(parent.target, context)
                break
            if isinstance(parent, ast.withitem):
                if child is parent.context_expr and \
                        parent.optional_vars is not None:
                    return self._target_handle(
                        parent.optional_vars, context)
                break
            if isinstance(parent, (ast.Tuple, ast.List)):
                grand = self.module.parents.get(id(parent))
                if isinstance(grand, ast.Assign) and grand.value is parent \
                        and isinstance(grand.targets[0],
                                       (ast.Tuple, ast.List)) and \
                        len(grand.targets[0].elts) == len(parent.elts):
                    for index, element in enumerate(parent.elts):
                        if element is child:
                            return self._target_handle(
                                grand.targets[0].elts[index], context)
                child, parent = parent, grand
                continue
            if isinstance(parent, ast.Call):
                func = parent.func
                if isinstance(func, ast.Attribute) and \
                        func.attr in CONTAINER_ADDERS and \
                        any(a is child for a in parent.args):
                    return self._target_handle(func.value, context)
                break
            if isinstance(parent, PASS_THROUGH) or \
                    isinstance(parent, ast.comprehension):
                child, parent = parent, self.module.parents.get(id(parent))
                continue
            break
        return self.synthetic(node), None

    def _target_handle(self, target, context):
        while isinstance(target, ast.Subscript):
            target = target.value
        handle = self.project.handle(target, context.scope)
        if handle is None:
            return None, None
        return handle, self.text(target)

    def _callback(self, expr, context):
        """(function id, function scope, offset) a callback argument names.

        `offset` is 1 for a method named through its class (its first
        argument is the object).
        """
        if expr is None:
            return None, None, 0
        if isinstance(expr, ast.Lambda):
            scope = self.module.scopes[id(expr)]
            self._consumed.add(id(expr))
            self._registered.add(scope.id)
            return scope.id, scope, 0
        if isinstance(expr, ast.Call):
            called = self.project.value(expr.func, context.scope)
            api = python_api.lookup(called.ref) \
                if called is not None and called.kind == EXT else None
            if api is not None and api.role == python_api.PARTIAL and \
                    expr.args:
                function_id, scope, offset = self._callback(
                    expr.args[0], context)
                if scope is not None:
                    self._bind(scope, expr.args[1:], expr.keywords,
                               context, offset)
                return function_id, scope, 0
            return None, None, 0
        value = self.project.value(expr, context.scope)
        if value is not None and value.kind == PARTIAL:
            value = value.ref
        if value is None:
            return None, None, 0
        if value.kind in (FUNC, BOUND):
            self._consumed.add(id(expr))
            self._registered.add(value.ref.id)
            offset = 1 if value.kind == FUNC and \
                value.ref.self_kind == 'obj' else 0
            return value.ref.id, value.ref, offset
        if value.kind == STUB:
            self._consumed.add(id(expr))
            stub_id = self._stub(value)
            self._registered.add(stub_id)
            return stub_id, None, 0
        return None, None, 0

    # --- argument helpers -------------------------------------------------

    def _topic(self, expr, context):
        """(the name, is it known): known when a constant string.

        As in C++, a name is known when it is a literal, a constant (a
        name or attribute assigned once), or built from known values;
        else it is given as written.
        """
        if expr is None:
            return None, False
        name = self.project.string(expr, context.scope)
        if name is not None:
            return name, True
        return self.text(expr), False

    def _msg_type(self, expr, context):
        if expr is None:
            return None
        value = self.project.value(expr, context.scope)
        if value is not None and value.kind == EXT:
            return normalize_msg_type(value.ref)
        return normalize_msg_type(self.text(expr))

    def _rate_hz(self, expr, unit, context):
        """Hz of a rate or period argument when it is constant."""
        if expr is None:
            return None
        if unit == python_api.HZ:
            hz = self.project.number(expr, context.scope)
            return recorder.round_rate(hz) if hz and hz > 0 else None
        seconds = self._seconds(expr, context)
        return recorder.rate_of_period(seconds)

    def _seconds(self, expr, context):
        if isinstance(expr, ast.Call):
            called = self.project.value(expr.func, context.scope)
            if called is None or called.kind not in (EXT, EXTBOUND) or \
                    called.ref not in python_api.DURATIONS:
                return None
            total = 0.0
            for keyword, position, scale in \
                    python_api.DURATIONS[called.ref]:
                argument = call_argument(expr, (position, keyword))
                if argument is None:
                    continue
                number = self.project.number(argument, context.scope)
                if number is None:
                    return None
                total += number * scale
            return total if total > 0 else None
        number = self.project.number(expr, context.scope)
        return number if number and number > 0 else None

    def _ros1_form(self, api, node, context):
        """Whether a call has the ROS 1 form of an API of both.

        message_filters.Subscriber(topic, Type) rather than (node, Type,
        topic); InteractiveMarkerServer(topic_ns) rather than (node,
        topic_ns).
        """
        keywords = {k.arg for k in node.keywords}
        if keywords & set(api.ros2_keywords):
            return False
        if keywords & set(api.ros1_keywords):
            return True
        positional = []
        for argument in node.args:
            if isinstance(argument, ast.Starred):
                break
            positional.append(argument)
        if positional and (
                isinstance(positional[0], ast.JoinedStr) or
                self.project.string(positional[0], context.scope)
                is not None):
            return True
        return len(positional) < api.ros2_arity

    def _elements(self, expr, context):
        """The expressions of a list/tuple argument (or the one given)."""
        if isinstance(expr, ast.Name):
            owner = lookup(context.scope, expr.id)
            entries = owner.bindings.get(expr.id, ()) if owner else ()
            for kind, payload, _ in entries:
                if kind == 'assign' and \
                        isinstance(payload, (ast.List, ast.Tuple)):
                    return payload.elts
        if isinstance(expr, (ast.List, ast.Tuple)):
            return expr.elts
        return [expr] if expr is not None else []


_HANDLERS = {
    ast.FunctionDef: _Extractor._visit_def,
    ast.AsyncFunctionDef: _Extractor._visit_def,
    ast.Lambda: _Extractor._visit_lambda,
    ast.ClassDef: _Extractor._visit_class,
    ast.While: _Extractor._visit_while,
    ast.For: _Extractor._visit_for,
    ast.AsyncFor: _Extractor._visit_for,
    ast.If: _Extractor._visit_if,
    ast.IfExp: _Extractor._visit_ifexp,
    ast.BoolOp: _Extractor._visit_boolop,
    ast.Call: _Extractor._visit_call,
    ast.Name: _Extractor._visit_name,
    ast.Attribute: _Extractor._visit_attribute,
    ast.Import: _Extractor._visit_import,
    ast.ImportFrom: _Extractor._visit_import,
}
for _node_type in TRY_NODES:
    _HANDLERS[_node_type] = _Extractor._visit_try
for _node_type in COMPREHENSIONS:
    _HANDLERS[_node_type] = _Extractor._visit_comprehension
if hasattr(ast, 'Match'):
    _HANDLERS[ast.Match] = _Extractor._visit_match

_ROLES = {
    ros_api.PUBLISHER: _Extractor._on_publisher,
    ros_api.SUBSCRIBER: _Extractor._on_subscriber,
    ros_api.TIMER: _Extractor._on_timer,
    ros_api.SERVICE: _Extractor._on_service,
    ros_api.ACTION_SERVER: _Extractor._on_action_server,
    ros_api.ACTION_CLIENT: _Extractor._on_action_client,
    ros_api.PUBLISH: _Extractor._on_publish,
    ros_api.RATE: _Extractor._on_rate,
    ros_api.RATE_SLEEP: _Extractor._on_rate_sleep,
    ros_api.SYNC: _Extractor._on_sync,
    ros_api.REGISTER_CALLBACK: _Extractor._on_register_callback,
    ros_api.NODE_HANDLE: _Extractor._on_node_handle,
    python_api.SERVICE_CLIENT: _Extractor._on_service_client,
    ros_api.PARAM_READ: _Extractor._on_param_read,
}


def _element_of(target, iterated, name):
    """The container whose elements a loop's `target` binds `name` to."""
    if isinstance(target, ast.Name):
        return iterated if target.id == name else None
    if not isinstance(target, (ast.Tuple, ast.List)) or \
            len(target.elts) != 2 or not isinstance(iterated, ast.Call):
        return None
    second = target.elts[1]
    if not isinstance(second, ast.Name) or second.id != name:
        return None
    function = iterated.func
    # enumerate(pubs), pubs.items()
    if isinstance(function, ast.Name) and function.id == 'enumerate' and \
            iterated.args:
        return iterated.args[0]
    if isinstance(function, ast.Attribute) and function.attr == 'items':
        return function.value
    return None
