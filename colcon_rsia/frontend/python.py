# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The Python front end: a walk of one module's syntax tree to its facts.

The analysed code is read with :mod:`ast` only: it is never imported or
executed. Names are resolved through the module's imports (``import rospy``,
``from rclpy.node import Node``, ``import rclpy.node as rn``, relative
imports) and, for the package's own modules (``package_modules``), through
their code, parsed the same way; a call is recognised by the canonical name
of what it calls, looked up in :mod:`colcon_rsia.frontend.python_api`.

Ids (the same meaning as the C++ front end's USRs):

* functions: ``module:func``, ``module:Class.method``, nested functions
  ``module:outer.inner``; the module body is the function
  ``module:<module>``; lambdas ``lambda@<file>:<line>:<col>`` (named
  ``lambda@<file>:<line>``), ``<file>`` relative to the package;
* handles (the variable or attribute an object is stored in): locals
  ``module:func.name``, globals ``module:name``, attributes of a package
  class ``module:Class.attr`` where ``Class`` is the most basic class of
  the package (along the inheritance) that assigns the attribute, so that a
  publisher created in a base class in one module and used by a subclass in
  another is one handle; an object created and used without being stored
  ``new@<file>:<line>:<col>``;
* loops: ``<file>@<line>:<col>``.

Objects are typed by a small flow-insensitive evaluation: what a name or an
attribute is assigned anywhere in its scope (``self.x = ...`` in any method
of the class or its package bases), what a package function returns, the
classes of the package (``Talker()`` is an instance of ``Talker``;
``self`` in a method of a subclass of ``rclpy.node.Node`` is a node, so
``self.create_publisher(...)`` is a ROS call). A call through ``self`` of a
method the class does not define (a hook a subclass provides) goes to a
stub function ``module:Class.method``, and every method of a class gets a
call edge from the same method of each of its package base classes
(``Base.m`` may run ``Sub.m``); constructors and other dunder methods
excepted.

Left out: calls through objects passed as untyped parameters (except the
duck-typed methods of ``python_api.DUCK_METHODS`` and the handle aliases
made by calls with a handle as argument), objects stored in containers
(one handle per container), decorators that replace functions, ``exec``
and other dynamic code, ``getattr`` with computed names.
"""

import ast
import io
import os
import re
import string
import tokenize

from colcon_rsia import model
from colcon_rsia import safe_files
from colcon_rsia.frontend import python_api
from colcon_rsia.frontend import ros_api

MODULE_FUNCTION = '<module>'

# how deep the evaluation of one expression may go (names bound to names…)
MAX_DEPTH = 32
# a name longer than this is no topic name: not computed
MAX_STRING = 1000
# parsed modules kept between calls (keyed by path and stat)
_CACHE_LIMIT = 512
_MODULE_CACHE = {}

FUNCTION_NODES = (ast.FunctionDef, ast.AsyncFunctionDef)
SCOPE_NODES = FUNCTION_NODES + (ast.Lambda, ast.ClassDef)
LOOP_NODES = (ast.For, ast.AsyncFor, ast.While)
COMPREHENSIONS = (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)
TRY_NODES = tuple(t for t in (ast.Try, getattr(ast, 'TryStar', None)) if t)
# method calls that store their argument in the object they are called on
CONTAINER_ADDERS = frozenset({
    'append', 'appendleft', 'extend', 'add', 'insert', 'setdefault',
    '__setitem__'})
# expressions a created object passes through on its way to a variable
PASS_THROUGH = (ast.Set, ast.Dict, ast.Starred, ast.IfExp, ast.Await,
                ast.BoolOp) + COMPREHENSIONS

# kinds of evaluated values
MODULE = 'module'      # a module of the package (ref: dotted name)
EXT = 'ext'            # something outside the package (ref: dotted name)
INST = 'inst'          # an object of an outside class (ref: its name)
EXTBOUND = 'extbound'  # a method of an outside object (ref: dotted name)
FUNC = 'func'          # a package function, lambda or unbound method
BOUND = 'bound'        # a package method bound to its object
CLASS = 'class'        # a package class
OBJ = 'obj'            # an object of a package class
STUB = 'stub'          # a method a package class calls but lacks
SUPER = 'super'        # super() in a method of a package class
NUM = 'num'
STR = 'str'
PARTIAL = 'partial'    # functools.partial(f, …): ref is f's value


class SourceError(Exception):
    """A module that cannot be read or parsed (one line, no file name)."""


def read_module(path, *, roots=None):
    """Parse a Python file without running it; return (tree, text).

    :param roots: the directories the file's real path must be inside
    :raises SourceError: when the file cannot be read, decoded or parsed
    """
    try:
        data = safe_files.read_bytes(path, roots=roots)
    except OSError as e:
        raise SourceError(f'cannot be read ({e.strerror or e})') from None
    try:
        encoding, _ = tokenize.detect_encoding(io.BytesIO(data).readline)
        text = data.decode(encoding)
    except SyntaxError as e:
        message = f'not UTF-8 text and no usable coding declaration ({e})'
        raise SourceError(message) from None
    except LookupError as e:
        raise SourceError(f'unknown source encoding ({e})') from None
    except UnicodeDecodeError as e:
        message = (f'not valid {e.encoding.upper()} text '
                   f'(byte {e.start}: {e.reason})')
        raise SourceError(message) from None
    try:
        return ast.parse(text, filename=path), text
    except SyntaxError as e:
        raise SourceError(
            f'syntax error at line {e.lineno}: {e.msg}') from None
    except (ValueError, RecursionError, MemoryError) as e:
        reason = str(e) or {
            RecursionError: 'nested too deeply', MemoryError: 'too large',
        }.get(type(e), type(e).__name__)
        raise SourceError(f'cannot be parsed ({reason})') from None


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
    :rtype: colcon_rsia.model.TuFacts
    """
    package_path = os.path.abspath(package_path)
    relpath = os.path.relpath(os.path.abspath(path), package_path)
    facts = model.TuFacts(source=relpath, files=[relpath])
    modules = dict(package_modules)
    modules[module_name] = path
    project = _Project(package_path, modules)
    try:
        module = project.load(module_name)
    except SourceError as e:
        facts.diagnostics.append(f'{relpath}: {e}')
        return facts
    try:
        _Extractor(project, module, facts).run()
    except RecursionError:
        return model.TuFacts(source=relpath, diagnostics=[
            f'{relpath}: too deeply nested to analyse'])
    return facts


# --- the index of a module: scopes, bindings, classes ----------------------

class _Scope:
    """A module, class, function or lambda body and the names it binds."""

    def __init__(self, kind, module, node, qualname, parent, cls=None):
        self.kind = kind            # module | class | function | lambda
        self.module = module
        self.node = node
        self.qualname = qualname
        self.parent = parent        # the lexically enclosing scope
        self.cls = cls              # methods: their class; classes: itself
        # name -> [(kind, payload, scope the payload is evaluated in)]
        self.bindings = {}
        self.params = []            # positional (no self), then keyword-only
        self.annotations = {}
        self.self_name = None       # a method's first parameter
        self.self_kind = None       # 'obj' (self) | 'class' (cls) | None
        self.globals = set()
        self.nonlocals = set()
        self.returns = []
        if kind == 'module':
            self.id = f'{module.name}:{MODULE_FUNCTION}'
        elif kind == 'lambda':
            self.id = (f'lambda@{module.relpath}:{node.lineno}:'
                       f'{node.col_offset}')
        elif kind == 'function':
            self.id = f'{module.name}:{qualname}'
        else:
            self.id = None

    def handle(self, name):
        """The handle id of this scope's variable `name`."""
        if self.kind == 'module':
            return f'{self.module.name}:{name}'
        if self.kind == 'class':
            return f'{self.cls.id}.{name}'
        return f'{self.id}.{name}'


class _Class:
    """A class of the package."""

    def __init__(self, module, node, qualname, outer):
        self.module = module
        self.node = node
        self.qualname = qualname
        self.outer = outer          # where the class statement runs
        self.id = f'{module.name}:{qualname}'
        self.location = f'{module.relpath}:{node.lineno}'
        self.scope = None
        self.methods = {}           # name -> function scope
        self.attrs = {}             # self.<name> = value: [(value, scope)]


class _Module:
    """One parsed module of the package and its scopes."""

    def __init__(self, name, path, relpath, tree, text):
        self.name = name
        self.path = path
        self.relpath = relpath
        self.tree = tree
        self.text = text
        self.is_package = os.path.basename(path) == '__init__.py'
        self.parents = {}
        for node in ast.walk(tree):
            for child in ast.iter_child_nodes(node):
                self.parents[id(child)] = node
        self.scopes = {}            # id(node) -> scope of a def/lambda/class
        self.functions = []         # module, function and lambda scopes
        self.classes = []
        self.scope = _Scope('module', self, tree, '', None)
        self.functions.append(self.scope)
        _Binder(self).bind(self.scope, tree.body)

    def import_base(self, node):
        """The absolute dotted module an ``ImportFrom`` imports from."""
        if not node.level:
            return node.module or ''
        parts = self.name.split('.')
        if not self.is_package:
            parts = parts[:-1]
        drop = node.level - 1
        if drop:
            parts = parts[:-drop] if drop < len(parts) else []
        base = '.'.join(parts)
        if node.module:
            base = f'{base}.{node.module}' if base else node.module
        return base


def _own_children(node):
    """Children of a node that run in the scope the node is in."""
    if isinstance(node, FUNCTION_NODES):
        args = node.args
        return node.decorator_list + args.defaults + [
            d for d in args.kw_defaults if d is not None]
    if isinstance(node, ast.Lambda):
        return node.args.defaults + [
            d for d in node.args.kw_defaults if d is not None]
    if isinstance(node, ast.ClassDef):
        return node.decorator_list + node.bases + [
            k.value for k in node.keywords]
    return list(ast.iter_child_nodes(node))


def _region(nodes):
    """The nodes of one scope's own code, in source order."""
    todo = list(reversed(nodes))
    while todo:
        node = todo.pop()
        yield node
        todo.extend(reversed(_own_children(node)))


def _lookup(scope, name):
    """The scope whose variable `name` is (LEGB), or None (a builtin)."""
    current = scope
    while current is not None:
        if name in current.globals:
            return current.module.scope
        if name not in current.nonlocals and \
                (current is scope or current.kind != 'class') and \
                name in current.bindings:
            return current
        current = current.parent
    return None


def _decorator_names(node):
    names = set()
    for decorator in node.decorator_list:
        if isinstance(decorator, ast.Name):
            names.add(decorator.id)
        elif isinstance(decorator, ast.Attribute):
            names.add(decorator.attr)
    return names


class _Binder:
    """Fills the scopes of a module: what each name is bound to."""

    def __init__(self, module):
        self.module = module

    def bind(self, scope, body):
        nodes = list(_region(body))
        for node in nodes:
            if isinstance(node, ast.Global):
                scope.globals.update(node.names)
            elif isinstance(node, ast.Nonlocal):
                scope.nonlocals.update(node.names)
        for node in nodes:
            self._node(scope, node)

    def _add(self, scope, name, binding):
        if name in scope.globals:
            owner = scope.module.scope
        elif name in scope.nonlocals:
            owner = scope.parent
            while owner is not None and owner.kind == 'class':
                owner = owner.parent
            owner = owner or scope
        else:
            owner = scope
        owner.bindings.setdefault(name, []).append(binding)

    def _node(self, scope, node):
        if isinstance(node, FUNCTION_NODES):
            child = self._function(scope, node)
            self._add(scope, node.name, ('def', child, scope))
        elif isinstance(node, ast.Lambda):
            self._lambda(scope, node)
        elif isinstance(node, ast.ClassDef):
            cls = self._class(scope, node)
            self._add(scope, node.name, ('class', cls, scope))
        elif isinstance(node, ast.Assign):
            for target in node.targets:
                self._target(scope, target, node.value)
        elif isinstance(node, (ast.AnnAssign, ast.NamedExpr)):
            self._target(scope, node.target, node.value)
        elif isinstance(node, (ast.AugAssign, ast.For, ast.AsyncFor,
                               ast.comprehension)):
            self._target(scope, node.target, None)
        elif isinstance(node, ast.withitem):
            if node.optional_vars is not None:
                self._target(scope, node.optional_vars, node.context_expr)
        elif isinstance(node, ast.ExceptHandler):
            if node.name:
                self._add(scope, node.name, ('unknown', None, scope))
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.asname:
                    self._add(scope, alias.asname,
                              ('import', alias.name, scope))
                else:
                    first = alias.name.split('.')[0]
                    self._add(scope, first, ('import', first, scope))
        elif isinstance(node, ast.ImportFrom):
            base = self.module.import_base(node)
            for alias in node.names:
                if alias.name == '*':
                    continue
                dotted = f'{base}.{alias.name}' if base else alias.name
                self._add(scope, alias.asname or alias.name,
                          ('import', dotted, scope))
        elif isinstance(node, ast.Return):
            if node.value is not None:
                scope.returns.append(node.value)
        elif type(node).__name__ in ('MatchAs', 'MatchStar'):
            if node.name:
                self._add(scope, node.name, ('unknown', None, scope))

    def _target(self, scope, target, value):
        if isinstance(target, ast.Name):
            if value is None:
                self._add(scope, target.id, ('unknown', None, scope))
            else:
                self._add(scope, target.id, ('assign', value, scope))
        elif isinstance(target, (ast.Tuple, ast.List)):
            pairs = isinstance(value, (ast.Tuple, ast.List)) and \
                len(value.elts) == len(target.elts) and not any(
                    isinstance(e, ast.Starred)
                    for e in target.elts + value.elts)
            for index, element in enumerate(target.elts):
                self._target(
                    scope, element, value.elts[index] if pairs else None)
        elif isinstance(target, ast.Starred):
            self._target(scope, target.value, None)
        elif isinstance(target, ast.Attribute) and \
                isinstance(target.value, ast.Name):
            owner = _lookup(scope, target.value.id)
            if owner is not None and owner.self_kind == 'obj' and \
                    owner.self_name == target.value.id:
                owner.cls.attrs.setdefault(target.attr, []).append(
                    (value, scope))

    def _function(self, scope, node):
        qualname = f'{scope.qualname}.{node.name}' if scope.qualname \
            else node.name
        cls = scope.cls if scope.kind == 'class' else None
        child = _Scope('function', self.module, node, qualname, scope, cls)
        decorators = _decorator_names(node) if cls is not None else set()
        self._params(child, node.args, cls is not None and
                     'staticmethod' not in decorators,
                     'class' if 'classmethod' in decorators else 'obj')
        self.module.scopes[id(node)] = child
        self.module.functions.append(child)
        if cls is not None:
            cls.methods[node.name] = child
        self.bind(child, node.body)
        return child

    def _lambda(self, scope, node):
        child = _Scope('lambda', self.module, node, scope.qualname, scope)
        self._params(child, node.args, False, None)
        child.returns.append(node.body)
        self.module.scopes[id(node)] = child
        self.module.functions.append(child)
        self.bind(child, [node.body])

    def _class(self, scope, node):
        qualname = f'{scope.qualname}.{node.name}' if scope.qualname \
            else node.name
        cls = _Class(self.module, node, qualname, scope)
        body = _Scope('class', self.module, node, qualname, scope, cls)
        cls.scope = body
        self.module.scopes[id(node)] = body
        self.module.classes.append(cls)
        self.bind(body, node.body)
        return cls

    def _params(self, scope, args, is_method, self_kind):
        positional = list(getattr(args, 'posonlyargs', [])) + list(args.args)
        if is_method and positional:
            scope.self_name = positional[0].arg
            scope.self_kind = self_kind
            scope.bindings[positional[0].arg] = [('param', None, scope)]
            positional = positional[1:]
        for arg in positional + list(args.kwonlyargs):
            scope.params.append(arg.arg)
            scope.bindings[arg.arg] = [('param', None, scope)]
            if arg.annotation is not None:
                scope.annotations[arg.arg] = arg.annotation
        for arg in (args.vararg, args.kwarg):
            if arg is not None:
                scope.bindings[arg.arg] = [('unknown', None, scope)]


def _load_module(name, path, package_path):
    """A module's index, parsed again only when its file changed."""
    path = os.path.abspath(path)
    try:
        st = os.stat(path)
    except OSError as e:
        raise SourceError(f'cannot be read ({e.strerror or e})') from None
    key = (path, name, package_path)
    stamp = (st.st_mtime_ns, st.st_size)
    cached = _MODULE_CACHE.get(key)
    if cached is not None and cached[0] == stamp:
        return cached[1]
    tree, text = read_module(path, roots=[package_path])
    module = _Module(name, path, os.path.relpath(path, package_path),
                     tree, text)
    if len(_MODULE_CACHE) >= _CACHE_LIMIT:
        _MODULE_CACHE.clear()
    _MODULE_CACHE[key] = (stamp, module)
    return module


# --- evaluation: what an expression stands for -----------------------------

class _Value:
    """What an expression evaluates to, as far as the analysis can tell."""

    __slots__ = ('kind', 'ref')

    def __init__(self, kind, ref):
        self.kind = kind
        self.ref = ref


class _Project:
    """The package's modules and the evaluation of expressions in them."""

    def __init__(self, package_path, package_modules):
        self.package_path = package_path
        self.package_modules = package_modules
        self._modules = {}
        self._memo = {}
        self._active = set()
        self._numbers_active = set()
        self._strings_active = set()
        self._mro = {}

    def load(self, name):
        """The module `name`; raise SourceError when it cannot be parsed."""
        module = _load_module(
            name, self.package_modules[name], self.package_path)
        self._modules[name] = module
        return module

    def module(self, name):
        """The module `name` of the package, or None."""
        if name not in self._modules:
            try:
                self._modules[name] = self.load(name) \
                    if name in self.package_modules else None
            except SourceError:
                self._modules[name] = None
        return self._modules[name]

    # values ---------------------------------------------------------------

    def value(self, expr, scope, depth=0):
        """Evaluate an expression in a scope; None when unknown.

        Every result is kept: an expression met again while it is being
        evaluated (``text = text.replace(...)``) is None there, so that the
        work is linear in the size of the code (the result depends only on
        the order of evaluation, which the walk fixes).
        """
        if expr is None or depth > MAX_DEPTH:
            return None
        key = (id(expr), id(scope))
        if key in self._memo:
            return self._memo[key]
        if key in self._active:
            return None
        self._active.add(key)
        try:
            result = self._value(expr, scope, depth + 1)
        finally:
            self._active.discard(key)
        self._memo[key] = result
        return result

    def _value(self, expr, scope, depth):
        if isinstance(expr, ast.Constant):
            value = expr.value
            if isinstance(value, bool) or value is None:
                return None
            if isinstance(value, (int, float)):
                return _Value(NUM, value)
            if isinstance(value, str):
                return _Value(STR, value)
            return None
        if isinstance(expr, ast.Name):
            return self.name_value(scope, expr.id, depth)
        if isinstance(expr, ast.Attribute):
            base = self.value(expr.value, scope, depth)
            return self.attr(base, expr.attr, depth) if base else None
        if isinstance(expr, ast.Call):
            return self._call_value(expr, scope, depth)
        if isinstance(expr, ast.Lambda):
            return _Value(FUNC, scope.module.scopes[id(expr)])
        if isinstance(expr, (ast.BinOp, ast.UnaryOp)):
            number = self.number(expr, scope, depth)
            return _Value(NUM, number) if number is not None else None
        if isinstance(expr, ast.IfExp):
            return self.value(expr.body, scope, depth) or \
                self.value(expr.orelse, scope, depth)
        if isinstance(expr, (ast.Await, ast.NamedExpr)):
            return self.value(expr.value, scope, depth)
        return None

    def name_value(self, scope, name, depth):
        owner = _lookup(scope, name)
        if owner is None:
            return None
        for kind, payload, where in owner.bindings.get(name, ()):
            if kind == 'import':
                result = self.resolve_dotted(payload, depth)
            elif kind == 'def':
                result = _Value(FUNC, payload)
            elif kind == 'class':
                result = _Value(CLASS, payload)
            elif kind == 'assign':
                result = self.value(payload, where, depth)
            elif kind == 'param':
                result = self._param_value(owner, name, depth)
            else:
                result = None
            if result is not None:
                return result
        return None

    def _param_value(self, scope, name, depth):
        if name == scope.self_name and scope.cls is not None:
            return _Value(OBJ if scope.self_kind == 'obj' else CLASS,
                          scope.cls)
        annotation = scope.annotations.get(name)
        if annotation is not None:
            kind = self.value(annotation, scope.parent, depth)
            if kind is not None and kind.kind == CLASS:
                return _Value(OBJ, kind.ref)
            if kind is not None and kind.kind == EXT:
                return _Value(INST, kind.ref)
        return None

    def resolve_dotted(self, dotted, depth=0):
        """The value of an absolute dotted name (an import)."""
        parts = dotted.split('.')
        for cut in range(len(parts), 0, -1):
            head = '.'.join(parts[:cut])
            if head in self.package_modules:
                value = _Value(MODULE, head)
                for attr in parts[cut:]:
                    value = self.attr(value, attr, depth)
                    if value is None:
                        return None
                return value
        return _Value(EXT, python_api.canonical(dotted))

    def attr(self, base, name, depth):
        """The value of ``base.name``."""
        kind = base.kind
        if kind == MODULE:
            module = self.module(base.ref)
            if module is not None and name in module.scope.bindings:
                return self.name_value(module.scope, name, depth)
            sub = f'{base.ref}.{name}'
            if sub in self.package_modules:
                return _Value(MODULE, sub)
            # not defined in the package's code: generated (msg, srv)
            return _Value(EXT, python_api.canonical(sub))
        if kind == EXT:
            return _Value(EXT, python_api.canonical(f'{base.ref}.{name}'))
        if kind == INST:
            return _Value(
                EXTBOUND, python_api.canonical(f'{base.ref}.{name}'))
        if kind in (OBJ, CLASS):
            return self.member(base.ref, name, depth, instance=kind == OBJ)
        if kind == SUPER:
            return self.member(base.ref, name, depth, instance=True,
                               after=base.ref)
        return None

    def mro(self, cls):
        """([package classes, most derived first], [outside bases], unknown).

        `unknown` tells that some base could not be resolved.
        """
        if cls in self._mro:
            return self._mro[cls]
        self._mro[cls] = ([cls], [], True)  # while being computed
        classes = []
        outside = []
        unknown = False
        todo = [cls]
        while todo:
            current = todo.pop(0)
            if current in classes:
                continue
            classes.append(current)
            bases = []
            for base in current.node.bases:
                if isinstance(base, ast.Name) and base.id == 'object' and \
                        _lookup(current.outer, 'object') is None:
                    continue
                value = self.value(base, current.outer)
                if value is None:
                    unknown = True
                elif value.kind == CLASS:
                    bases.append(value.ref)
                elif value.kind == EXT:
                    name = python_api.canonical(value.ref)
                    if name not in ('object', 'builtins.object') and \
                            name not in outside:
                        outside.append(name)
                else:
                    unknown = True
            # depth first, left to right: close to the C3 order
            todo[0:0] = bases
        result = (classes, outside, unknown)
        self._mro[cls] = result
        return result

    def member(self, cls, name, depth, instance, after=None):
        """The value of an attribute of a package class or its objects."""
        classes, outside, unknown = self.mro(cls)
        if after is not None:
            classes = classes[classes.index(after) + 1:] \
                if after in classes else classes[1:]
        for current in classes:
            method = current.methods.get(name)
            if method is None:
                continue
            if method.self_kind is None:
                return _Value(FUNC, method)       # staticmethod
            if method.self_kind == 'class' or instance:
                return _Value(BOUND, method)
            return _Value(FUNC, method)           # unbound, through the class
        assigned = False
        for current in classes:
            for value, where in current.attrs.get(name, ()) \
                    if instance else ():
                assigned = True
                result = self.value(value, where, depth) \
                    if value is not None else None
                if result is not None:
                    return result
            if name in current.scope.bindings:
                assigned = True
                result = self.name_value(current.scope, name, depth)
                if result is not None:
                    return result
        if assigned:
            return None
        for base in outside:
            qualified = python_api.canonical(f'{base}.{name}')
            if python_api.lookup(qualified) is not None:
                return _Value(EXTBOUND, qualified)
            # super().__init__("name"): the outside base's constructor
            if name == '__init__' and python_api.lookup(
                    python_api.canonical(base)) is not None:
                return _Value(EXTBOUND, python_api.canonical(base))
        if unknown or after is not None:
            return None
        node_only = all(b == python_api.NODE_CLASS for b in outside)
        dunder = name.startswith('__') and name.endswith('__')
        if instance and node_only and not dunder and \
                name not in python_api.NODE_METHODS:
            # called through self but defined by no class of the package:
            # a hook a subclass provides
            return _Value(STUB, (cls, name))
        if outside:
            return _Value(
                EXTBOUND, python_api.canonical(f'{outside[0]}.{name}'))
        return None

    def _call_value(self, call, scope, depth):
        func = call.func
        if isinstance(func, ast.Name) and func.id == 'super' and \
                _lookup(scope, 'super') is None:
            return self._super(call, scope, depth)
        called = self.value(func, scope, depth)
        if called is None:
            return None
        if called.kind == CLASS:
            return _Value(OBJ, called.ref)
        if called.kind == EXT:
            api = python_api.lookup(called.ref)
            if api is not None and api.role == python_api.PARTIAL:
                target = self.value(call.args[0], scope, depth) \
                    if call.args else None
                return _Value(PARTIAL, target) if target else None
            if api is not None and api.returns:
                return _Value(INST, api.returns)
            return _Value(INST, called.ref)
        if called.kind == EXTBOUND:
            api = python_api.lookup(called.ref)
            if api is not None and api.returns:
                return _Value(INST, api.returns)
            return None
        if called.kind in (FUNC, BOUND):
            for value in called.ref.returns:
                result = self.value(value, called.ref, depth)
                if result is not None:
                    return result
        return None

    def _super(self, call, scope, depth):
        if len(call.args) == 2:
            cls = self.value(call.args[0], scope, depth)
            if cls is not None and cls.kind == CLASS:
                return _Value(SUPER, cls.ref)
            return None
        current = scope
        while current is not None and not (
                current.kind == 'function' and current.cls is not None):
            current = current.parent
        if current is None:
            return None
        return _Value(SUPER, current.cls)

    # numbers (rates) -------------------------------------------------------

    def number(self, expr, scope, depth=0):
        """A constant number: literals, single-assignment names, arithmetic."""
        if depth > MAX_DEPTH:
            return None
        depth += 1
        if isinstance(expr, ast.Constant):
            value = expr.value
            if isinstance(value, (int, float)) and \
                    not isinstance(value, bool):
                return value
            return None
        if isinstance(expr, ast.UnaryOp):
            operand = self.number(expr.operand, scope, depth)
            if operand is None:
                return None
            if isinstance(expr.op, ast.USub):
                return -operand
            if isinstance(expr.op, ast.UAdd):
                return operand
            return None
        if isinstance(expr, ast.BinOp):
            return _arithmetic(
                expr.op, self.number(expr.left, scope, depth),
                self.number(expr.right, scope, depth))
        if isinstance(expr, ast.Name):
            owner = _lookup(scope, expr.id)
            return self._name_number(owner, expr.id, depth) \
                if owner is not None else None
        if isinstance(expr, ast.Attribute):
            return self._attribute_number(expr, scope, depth)
        if isinstance(expr, ast.Call) and isinstance(expr.func, ast.Name) \
                and expr.func.id in ('float', 'int') and \
                _lookup(scope, expr.func.id) is None and \
                len(expr.args) == 1 and not expr.keywords:
            return self.number(expr.args[0], scope, depth)
        return None

    def _name_number(self, owner, name, depth):
        entries = owner.bindings.get(name, ())
        if len(entries) != 1:
            return None  # rebound: not a constant
        key = (id(owner), name)
        if key in self._numbers_active:
            return None  # defined by itself
        self._numbers_active.add(key)
        try:
            kind, payload, where = entries[0]
            if kind == 'assign':
                return self.number(payload, where, depth + 1)
            if kind == 'import':
                module_name, _, attr = payload.rpartition('.')
                module = self.module(module_name) \
                    if module_name in self.package_modules else None
                if module is not None and attr in module.scope.bindings:
                    return self._name_number(module.scope, attr, depth + 1)
            return None
        finally:
            self._numbers_active.discard(key)

    def _attribute_number(self, expr, scope, depth):
        base = self.value(expr.value, scope, depth)
        if base is None:
            return None
        if base.kind == MODULE:
            module = self.module(base.ref)
            if module is not None:
                return self._name_number(module.scope, expr.attr, depth)
            return None
        if base.kind not in (OBJ, CLASS):
            return None
        sites = []
        for current in self.mro(base.ref)[0]:
            for value, where in current.attrs.get(expr.attr, ()):
                sites.append((value, where))
            for kind, payload, where in current.scope.bindings.get(
                    expr.attr, ()):
                sites.append((payload if kind == 'assign' else None, where))
        key = (id(base.ref), expr.attr)
        if len(sites) != 1 or sites[0][0] is None or \
                key in self._numbers_active:
            return None
        self._numbers_active.add(key)
        try:
            return self.number(sites[0][0], sites[0][1], depth)
        finally:
            self._numbers_active.discard(key)

    # strings (names) -----------------------------------------------------

    def sole_source(self, expr, scope, depth=0):
        """(expression, scope) a name or attribute is assigned, when once.

        None when it is bound more than once, not by ``=`` (a parameter,
        a loop variable), or cannot be found: its value is not known.
        """
        if isinstance(expr, ast.Name):
            owner = _lookup(scope, expr.id)
            return self._sole_binding(owner, expr.id, depth) \
                if owner is not None else None
        if not isinstance(expr, ast.Attribute):
            return None
        base = self.value(expr.value, scope, depth)
        if base is None:
            return None
        if base.kind == MODULE:
            module = self.module(base.ref)
            return self._sole_binding(module.scope, expr.attr, depth) \
                if module is not None else None
        if base.kind not in (OBJ, CLASS):
            return None
        sites = []
        for current in self.mro(base.ref)[0]:
            sites += current.attrs.get(expr.attr, [])
            sites += [(payload if kind == 'assign' else None, where)
                      for kind, payload, where in
                      current.scope.bindings.get(expr.attr, ())]
        if len(sites) != 1 or sites[0][0] is None:
            return None
        return sites[0]

    def _sole_binding(self, owner, name, depth):
        entries = owner.bindings.get(name, ())
        if len(entries) != 1 or depth > MAX_DEPTH:
            return None
        kind, payload, where = entries[0]
        if kind == 'assign':
            return payload, where
        if kind == 'import':
            module_name, _, attr = payload.rpartition('.')
            module = self.module(module_name) \
                if module_name in self.package_modules else None
            if module is not None:
                return self._sole_binding(module.scope, attr, depth + 1)
        return None

    def string(self, expr, scope, depth=0):
        """A constant string, as C++ names are resolved.

        Literals, names and attributes assigned once (module and class
        constants), ``+``, ``%`` with ``%s``, f-strings and ``str.format``
        over known strings and numbers.
        """
        if expr is None or depth > MAX_DEPTH:
            return None
        key = (id(expr), id(scope))
        if key in self._strings_active:
            return None  # defined by itself
        self._strings_active.add(key)
        try:
            text = self._string(expr, scope, depth + 1)
        finally:
            self._strings_active.discard(key)
        return text if text is None or len(text) <= MAX_STRING else None

    def _string(self, expr, scope, depth):
        if isinstance(expr, ast.Constant):
            return expr.value if isinstance(expr.value, str) else None
        if isinstance(expr, (ast.Name, ast.Attribute)):
            source = self.sole_source(expr, scope, depth)
            return self.string(source[0], source[1], depth) \
                if source is not None else None
        if isinstance(expr, ast.JoinedStr):
            parts = []
            for part in expr.values:
                if isinstance(part, ast.FormattedValue):
                    if part.format_spec is not None or \
                            part.conversion not in (-1, ord('s')):
                        return None
                    part = self._formattable(part.value, scope, depth)
                elif isinstance(part, ast.Constant):
                    part = str(part.value)
                if not isinstance(part, str):
                    return None
                parts.append(part)
            return ''.join(parts)
        if isinstance(expr, ast.BinOp) and isinstance(expr.op, ast.Add):
            left = self.string(expr.left, scope, depth)
            right = self.string(expr.right, scope, depth) \
                if left is not None else None
            return left + right if right is not None else None
        if isinstance(expr, ast.BinOp) and isinstance(expr.op, ast.Mod):
            return self._percent(expr, scope, depth)
        if isinstance(expr, ast.Call) and \
                isinstance(expr.func, ast.Attribute) and \
                expr.func.attr == 'format':
            return self._format(expr, scope, depth)
        return None

    def _formattable(self, expr, scope, depth):
        """A value as ``%s``/``{}`` print it: a known string or number."""
        text = self.string(expr, scope, depth)
        if text is not None:
            return text
        number = self.number(expr, scope, depth)
        return str(number) if number is not None else None

    def _percent(self, expr, scope, depth):
        """``'%s/cmd_vel' % name``: only ``%s`` (and ``%%``)."""
        template = self.string(expr.left, scope, depth)
        if template is None or re.search(r'%(?![s%])', template):
            return None
        items = expr.right.elts if isinstance(expr.right, ast.Tuple) \
            else [expr.right]
        values = [self._formattable(item, scope, depth) for item in items]
        if None in values:
            return None
        try:
            return template % tuple(values)
        except (TypeError, ValueError):
            return None

    def _format(self, call, scope, depth):
        """``'{}/scan'.format(ns)``: plain fields, no attribute or index."""
        template = self.string(call.func.value, scope, depth)
        if template is None or any(
                isinstance(a, ast.Starred) for a in call.args) or any(
                k.arg is None for k in call.keywords):
            return None
        try:
            fields = list(string.Formatter().parse(template))
        except ValueError:
            return None
        for _, field, spec, conversion in fields:
            if field is not None and (
                    spec or conversion not in (None, 's') or
                    not re.fullmatch(r'\d*|[A-Za-z_]\w*', field)):
                return None
        args = [self._formattable(a, scope, depth) for a in call.args]
        kwargs = {k.arg: self._formattable(k.value, scope, depth)
                  for k in call.keywords}
        if None in args or None in kwargs.values():
            return None
        try:
            return template.format(*args, **kwargs)
        except (IndexError, KeyError, ValueError):
            return None

    # handles -------------------------------------------------------------

    def handle(self, expr, scope):
        """The handle id of the variable/attribute an expression names."""
        if isinstance(expr, ast.Name):
            owner = _lookup(scope, expr.id)
            return owner.handle(expr.id) if owner is not None else None
        if isinstance(expr, ast.Attribute):
            base = self.value(expr.value, scope)
            if base is None:
                return None
            if base.kind in (OBJ, CLASS, SUPER):
                return self.attribute_handle(base.ref, expr.attr)
            if base.kind == MODULE:
                return f'{base.ref}:{expr.attr}'
            return None
        if isinstance(expr, ast.Subscript):
            return self.handle(expr.value, scope)
        return None

    def attribute_handle(self, cls, name):
        """``module:Class.attr`` of the most basic class that assigns it."""
        for current in reversed(self.mro(cls)[0]):
            if name in current.attrs or name in current.scope.bindings:
                return f'{current.id}.{name}'
        return f'{cls.id}.{name}'


def _arithmetic(op, left, right):
    if left is None or right is None:
        return None
    try:
        if isinstance(op, ast.Add):
            return left + right
        if isinstance(op, ast.Sub):
            return left - right
        if isinstance(op, ast.Mult):
            return left * right
        if isinstance(op, ast.Div):
            return left / right
        if isinstance(op, ast.FloorDiv):
            return left // right
        if isinstance(op, ast.Mod):
            return left % right
        if isinstance(op, ast.Pow) and abs(right) <= 64:
            return left ** right
    except (ArithmeticError, ValueError, TypeError):
        return None
    return None


def _round(value):
    # 1/0.1 is 9.999999999999998: keep the rate a person would write
    return round(float(value), 6) if value is not None else None


def _argument(call, spec):
    """The argument written for (position, keyword), or None."""
    if spec is None:
        return None
    position, keyword = spec
    if position is not None:
        for index, argument in enumerate(call.args):
            if isinstance(argument, ast.Starred):
                break
            if index == position:
                return argument
    if keyword:
        for kw in call.keywords:
            if kw.arg == keyword:
                return kw.value
    return None


# --- the walk of function bodies -------------------------------------------

class _Context:
    """Where the walk is inside one function body."""

    def __init__(self, scope, function, loops=(), conditional=0):
        self.scope = scope
        self.function = function
        # (loop id, conditional depth at the loop, loop node)
        self.loops = list(loops)
        self.conditional = conditional

    def loop_ids(self):
        return [loop_id for loop_id, _, _ in self.loops]


class _Extractor:
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
        self.facts.functions.append(model.Function(
            id=scope.id, name=name, location=location, class_id=class_id,
            params=[scope.handle(p) for p in scope.params]))
        context = _Context(scope, scope.id)
        body = [scope.node.body] if scope.kind == 'lambda' \
            else scope.node.body
        for node in body:
            self._visit(node, context)

    def _stub(self, value):
        cls, name = value.ref
        stub_id = f'{cls.id}.{name}'
        if stub_id not in self._stubs:
            self._stubs.add(stub_id)
            self.facts.functions.append(model.Function(
                id=stub_id, name=f'{cls.qualname}.{name}',
                location=cls.location, class_id=cls.id))
        return stub_id

    def _dispatch_edges(self):
        """``Base.m`` may run ``Sub.m``: an edge from each base's method."""
        for cls in self.module.classes:
            bases = self.project.mro(cls)[0][1:]
            for name, method in cls.methods.items():
                if name.startswith('__') and name.endswith('__'):
                    continue
                for base in bases:
                    self.facts.calls.append(model.Call(
                        caller=f'{base.id}.{name}', callee=method.id,
                        location=self.location(method.node)))

    def _add_call(self, context, callee, node, kind='call'):
        self.facts.calls.append(model.Call(
            caller=context.function, callee=callee,
            location=self.location(node), loops=context.loop_ids(),
            kind=kind))

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
        context.conditional += 1
        self._visit_all(nodes, context)
        context.conditional -= 1

    def _visit_def(self, node, context):
        # the body is a function of its own; decorators and defaults run here
        self._visit_all(_own_children(node), context)

    def _visit_lambda(self, node, context):
        self._visit_all(_own_children(node), context)
        lambda_id = self.module.scopes[id(node)].id
        parent = self.module.parents.get(id(node))
        if isinstance(parent, (ast.Assign, ast.AnnAssign, ast.NamedExpr)):
            self._lambdas_in_variables.add(lambda_id)
        if id(node) not in self._consumed:
            self._add_call(context, lambda_id, node, kind='ref')

    def _visit_class(self, node, context):
        self._visit_all(_own_children(node), context)
        inner = _Context(self.module.scopes[id(node)], context.function,
                         context.loops, context.conditional)
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
        context.loops.append(
            (self.loop_id(node), context.conditional, node))
        self._visit_all(body, context)
        context.loops.pop()

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
            return
        if kind == STUB:
            self._add_call(context, self._stub(called), node)
            return
        if kind == CLASS:
            init = self.project.member(called.ref, '__init__', 0, True)
            if init is not None and init.kind in (FUNC, BOUND):
                self._add_call(context, init.ref.id, node)
                self._bind(init.ref, node.args, node.keywords, context, 0)
            return
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
        if api is not None:
            handler = _ROLES.get(api.role)
            if handler is not None:
                handler(self, api, name, node, context)

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
            self.facts.string_arguments.append(model.StringArgument(
                caller=context.function, callee=function.id, index=position,
                value=argument.value))
            return
        handle = self._object_handle(argument, context)
        if handle is not None:
            self.facts.bindings.append(model.ParamBinding(
                callee=function.id, index=position, handle=handle))

    def _object_handle(self, expr, context):
        if isinstance(expr, ast.Call):
            return self.synthetic(expr)
        return self.project.handle(expr, context.scope)

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

    def _topic_handle(self, expr, context):
        """The parameter read a name that is not known comes from."""
        read = self._param_read_of(expr, context.scope, 0)
        return self._param_handle(*read) if read is not None else None

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
        param = self.project.string(
            _argument(node, api.name), context.scope)
        if param is None:
            return
        namespace = '~' if api.node_private else ''
        if param.startswith('~'):
            # rospy: a private parameter
            param, namespace = param[1:], '~'
        default = self.project.string(
            _argument(node, api.default), context.scope)
        self.facts.param_reads.append(model.ParamRead(
            function=context.function, name=param, default=default,
            handle=self._param_handle(node, context.scope), nh=namespace,
            location=self.location(node)))

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
            return _round(hz) if hz and hz > 0 else None
        seconds = self._seconds(expr, context)
        return _round(1.0 / seconds) if seconds else None

    def _seconds(self, expr, context):
        if isinstance(expr, ast.Call):
            called = self.project.value(expr.func, context.scope)
            if called is None or called.kind not in (EXT, EXTBOUND) or \
                    called.ref not in python_api.DURATIONS:
                return None
            total = 0.0
            for keyword, position, scale in \
                    python_api.DURATIONS[called.ref]:
                argument = _argument(expr, (position, keyword))
                if argument is None:
                    continue
                number = self.project.number(argument, context.scope)
                if number is None:
                    return None
                total += number * scale
            return total if total > 0 else None
        number = self.project.number(expr, context.scope)
        return number if number and number > 0 else None

    def _ros1_form(self, node):
        """message_filters.Subscriber(topic, Type) rather than (node, …)."""
        keywords = {k.arg for k in node.keywords}
        if keywords & {'topic', 'msg_type'}:
            return False
        if keywords & {'name', 'data_class'}:
            return True
        positional = []
        for argument in node.args:
            if isinstance(argument, ast.Starred):
                break
            positional.append(argument)
        if positional and (
                isinstance(positional[0], ast.JoinedStr) or
                (isinstance(positional[0], ast.Constant) and
                 isinstance(positional[0].value, str))):
            return True
        return len(positional) == 2

    def _elements(self, expr, context):
        """The expressions of a list/tuple argument (or the one given)."""
        if isinstance(expr, ast.Name):
            owner = _lookup(context.scope, expr.id)
            entries = owner.bindings.get(expr.id, ()) if owner else ()
            for kind, payload, _ in entries:
                if kind == 'assign' and \
                        isinstance(payload, (ast.List, ast.Tuple)):
                    return payload.elts
        if isinstance(expr, (ast.List, ast.Tuple)):
            return expr.elts
        return [expr] if expr is not None else []

    # --- roles (named after the python_api roles) -------------------------

    def _on_node_handle(self, api, name, node, context):
        """The node's name: ``rospy.init_node("n")``, ``Node("n", namespace=)``."""
        if name not in python_api.NODE_NAMING:
            return
        written = _argument(node, (0, 'name')) or \
            _argument(node, (0, 'node_name'))
        node_name, literal = self._topic(written, context)
        namespace, ns_literal = self._topic(
            _argument(node, (None, 'namespace')), context)
        # super().__init__(node_name) in a base class of the package: the
        # name its subclasses pass
        name_param = self.project.handle(written, context.scope) \
            if isinstance(written, ast.Name) else None
        self.facts.node_names.append(model.NodeNameFact(
            function=context.function, name=node_name if literal else None,
            namespace=namespace if ns_literal else None,
            location=self.location(node), name_param=name_param))

    def _on_publisher(self, api, name, node, context):
        msg_type = api.msg_type or self._msg_type(
            _argument(node, api.msg_type_arg), context)
        if api.implicit_topics:
            topics = [(topic, True) for topic in api.implicit_topics]
        else:
            argument = _argument(node, api.name)
            topic, literal = self._topic(argument, context)
            if topic is None:
                return
            topics = [(topic, literal)]
        handle, handle_name = self._target(node, context)
        for topic, literal in topics:
            self.facts.publishers.append(model.PublisherFact(
                function=context.function, api=name, topic=topic,
                topic_is_literal=literal, msg_type=msg_type, handle=handle,
                handle_name=handle_name, location=self.location(node),
                topic_handle=None if literal else self._topic_handle(
                    argument, context)))

    def _on_subscriber(self, api, name, node, context):
        name_arg, type_arg = api.name, api.msg_type_arg
        if api.ros1_form is not None and self._ros1_form(node):
            name_arg, type_arg = api.ros1_form
        msg_type = api.msg_type or self._msg_type(
            _argument(node, type_arg), context)
        if api.implicit_topics:
            topics = [(topic, True) for topic in api.implicit_topics]
        else:
            argument = _argument(node, name_arg)
            topic, literal = self._topic(argument, context)
            if topic is None:
                return
            topics = [(topic, literal)]
        callback, scope, offset = self._callback(
            _argument(node, api.callback), context)
        callback_args = _argument(node, api.callback_args)
        if scope is not None and callback_args is not None and \
                len(scope.params) > 1:
            # called as callback(msg, callback_args)
            self._bind_one(scope, 1, callback_args, context)
        handle, _ = self._target(node, context)
        for topic, literal in topics:
            self.facts.subscribers.append(model.SubscriberFact(
                function=context.function, api=name, topic=topic,
                topic_is_literal=literal, msg_type=msg_type, handle=handle,
                callback=callback, location=self.location(node),
                topic_handle=None if literal else self._topic_handle(
                    argument, context)))

    def _on_timer(self, api, name, node, context):
        callback, _, _ = self._callback(
            _argument(node, api.callback), context)
        period = _argument(node, api.period)
        self.facts.timers.append(model.TimerFact(
            function=context.function, api=name, callback=callback,
            period=self.text(period) if period is not None else '',
            rate_hz=self._rate_hz(period, api.period_unit, context),
            location=self.location(node)))

    def _on_service(self, api, name, node, context):
        service, _ = self._topic(_argument(node, api.name), context)
        callback, _, _ = self._callback(
            _argument(node, api.callback), context)
        self.facts.services.append(model.ServiceFact(
            function=context.function, api=name, name=service,
            callback=callback, location=self.location(node)))

    def _on_service_client(self, api, name, node, context):
        service, _ = self._topic(_argument(node, api.name), context)
        self.facts.clients.append(model.ClientFact(
            function=context.function, api=name, name=service,
            location=self.location(node)))

    def _on_action_server(self, api, name, node, context):
        self._action(api, name, node, context, 'server')

    def _on_action_client(self, api, name, node, context):
        self._action(api, name, node, context, 'client')

    def _action(self, api, name, node, context, role):
        registration = api.name is None
        action = None
        if not registration:
            action, _ = self._topic(_argument(node, api.name), context)
        callbacks = []
        specs = ((api.callback,) if api.callback else ()) + \
            api.extra_callbacks
        for spec in specs:
            callback, _, _ = self._callback(_argument(node, spec), context)
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
        self.facts.actions.append(model.ActionFact(
            function=context.function, api=label, role=role, name=action,
            callbacks=callbacks, handle=handle, location=location))

    def _on_publish(self, api, name, node, context):
        self.facts.publish_sites.append(model.PublishSite(
            function=context.function, api=name,
            handle=self._receiver(node, context),
            location=self.location(node), loops=context.loop_ids()))

    def _on_rate(self, api, name, node, context):
        handle, _ = self._target(node, context)
        if handle is None or handle.startswith('new@'):
            return  # a temporary Rate paces nothing
        argument = _argument(node, api.period)
        self.facts.rates.append(model.RateObject(
            handle=handle,
            rate_hz=self._rate_hz(argument, api.period_unit, context),
            expression=self.text(argument) if argument is not None else '',
            location=self.location(node)))

    def _on_rate_sleep(self, api, name, node, context):
        handle = self._receiver(node, context)
        if handle is None or handle.startswith('new@') or not context.loops:
            return  # rospy.Rate(10).sleep(): a new Rate never adapts
        loop_id, conditional, loop = context.loops[-1]
        if context.conditional != conditional:
            return  # a sleep that may be skipped does not pace the loop
        if self._assigned_in(loop, handle, context):
            return  # a Rate made anew in every iteration never adapts
        if _continue_before(loop, node):
            return  # an iteration may end before the sleep
        self.facts.paced_loops.append(model.PacedLoop(
            loop=loop_id, function=context.function, rate_handle=handle,
            location=self.location(loop),
            sleep_location=self.location(node)))

    def _assigned_in(self, loop, handle, context):
        for node in _region([loop]):
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
        for element in self._elements(_argument(node, api.inputs), context):
            handle = self._object_handle(element, context)
            if handle is not None:
                inputs.append(handle)
        handle, _ = self._target(node, context)
        self.facts.syncs.append(model.SyncFact(
            handle=handle, inputs=inputs, location=self.location(node)))

    def _on_register_callback(self, api, name, node, context):
        callback, _, _ = self._callback(
            _argument(node, api.callback), context)
        self.facts.registrations.append(model.Registration(
            function=context.function, handle=self._receiver(node, context),
            callback=callback, location=self.location(node)))


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
