# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The index of a Python module: its scopes, what they bind, its classes.

Part of the Python front end (see :mod:`colcon_rsia.frontend.python`):
modules are read without being run, and parsed modules are kept between
calls.
"""

import ast
import io
import os
import tokenize

from colcon_rsia import safe_files

# the function id of a module's body
MODULE_FUNCTION = '<module>'

# parsed modules kept between calls (keyed by path and stat)
CACHE_LIMIT = 512
MODULE_CACHE = {}

FUNCTION_NODES = (ast.FunctionDef, ast.AsyncFunctionDef)
SCOPE_NODES = FUNCTION_NODES + (ast.Lambda, ast.ClassDef)


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
        # `from X import *`: the absolute dotted X, in the order written
        self.star_imports = []
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


def own_children(node):
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


def region(nodes):
    """The nodes of one scope's own code, in source order."""
    todo = list(reversed(nodes))
    while todo:
        node = todo.pop()
        yield node
        todo.extend(reversed(own_children(node)))


def lookup(scope, name):
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
        nodes = list(region(body))
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
                    if base and base not in self.module.star_imports:
                        self.module.star_imports.append(base)
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
            owner = lookup(scope, target.value.id)
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


def load_module(name, path, package_path):
    """A module's index, parsed again only when its file changed."""
    path = os.path.abspath(path)
    try:
        st = os.stat(path)
    except OSError as e:
        raise SourceError(f'cannot be read ({e.strerror or e})') from None
    key = (path, name, package_path)
    stamp = (st.st_mtime_ns, st.st_size)
    cached = MODULE_CACHE.get(key)
    if cached is not None and cached[0] == stamp:
        return cached[1]
    tree, text = read_module(path, roots=[package_path])
    module = _Module(name, path, os.path.relpath(path, package_path),
                     tree, text)
    if len(MODULE_CACHE) >= CACHE_LIMIT:
        MODULE_CACHE.clear()
    MODULE_CACHE[key] = (stamp, module)
    return module
