# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Evaluation: what a Python expression stands for, as far as it can tell.

Part of the Python front end (see :mod:`colcon_rsia.frontend.python`).
"""

import ast
import contextlib
import re
import string

from colcon_rsia import python_arithmetic
from colcon_rsia.frontend import python_api
from colcon_rsia.frontend.python.scopes import load_module
from colcon_rsia.frontend.python.scopes import lookup
from colcon_rsia.frontend.python.scopes import SourceError
from colcon_rsia.frontend.python.stars import MAX_DEPTH
from colcon_rsia.frontend.python.stars import StarImports

# a name longer than this is no topic name: not computed
MAX_STRING = 1000

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


class _Value:
    """What an expression evaluates to, as far as the analysis can tell."""

    __slots__ = ('kind', 'ref')

    def __init__(self, kind, ref):
        self.kind = kind
        self.ref = ref


class Project(StarImports):
    """The package's modules and the evaluation of expressions in them."""

    def __init__(self, package_path, package_modules):  # noqa: D107
        self.package_path = package_path
        self.package_modules = package_modules
        self._modules = {}
        self._memo = {}
        self._active = set()
        self._numbers_active = set()
        self._strings_active = set()
        self._stars_active = set()
        self._mro = {}
        # (expression, scope) -> text or None: the values that stand in
        # for some expressions while strings are computed (substituting)
        self._substitute = None

    def load(self, name):
        """The module `name`; raise SourceError when it cannot be parsed."""
        module = load_module(
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

    def external(self, dotted):
        """The value of something outside the package."""
        return _Value(EXT, dotted)

    def name_value(self, scope, name, depth):
        """The value of a name read in a scope (where it is bound)."""
        if depth > MAX_DEPTH:
            return None  # modules importing names from each other
        owner = lookup(scope, name)
        if owner is None:
            return self._star_value(scope.module, name, depth)
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
                if cut == len(parts) and cut > 1:
                    # `from package import name`: the package's own name
                    # for it first (`from .name import *` in its
                    # __init__.py may bind a class of that name), then the
                    # submodule
                    bound = self._package_attribute(parts, depth)
                    if bound is not None:
                        return bound
                value = _Value(MODULE, head)
                for attr in parts[cut:]:
                    value = self.attr(value, attr, depth)
                    if value is None:
                        return None
                return value
        return _Value(EXT, python_api.canonical(dotted))

    def _package_attribute(self, parts, depth):
        """The value a package module binds for its submodule's name."""
        parent = self.module('.'.join(parts[:-1]))
        if parent is None or depth > MAX_DEPTH:
            return None
        bindings = parent.scope.bindings.get(parts[-1])
        if not bindings:
            return self._star_value(parent, parts[-1], depth)
        if any(kind == 'import' and payload == '.'.join(parts)
               for kind, payload, _ in bindings):
            return None  # the submodule itself
        return self.name_value(parent.scope, parts[-1], depth + 1)

    def attr(self, base, name, depth):
        """The value of ``base.name``."""
        kind = base.kind
        if kind == MODULE:
            module = self.module(base.ref)
            if module is not None and name in module.scope.bindings:
                return self.name_value(module.scope, name, depth + 1)
            if module is not None and self.star_source(module, name, depth) \
                    != (None, None):
                return self._star_value(module, name, depth)
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
                        lookup(current.outer, 'object') is None:
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
                lookup(scope, 'super') is None:
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
            owner = self.owner(scope, expr.id, depth)
            return self._name_number(owner, expr.id, depth) \
                if owner is not None else None
        if isinstance(expr, ast.Attribute):
            return self._attribute_number(expr, scope, depth)
        if isinstance(expr, ast.Call) and isinstance(expr.func, ast.Name) \
                and expr.func.id in ('float', 'int') and \
                lookup(scope, expr.func.id) is None and \
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
                owner = self.module_owner(module, attr, depth)[0] \
                    if module is not None else None
                if owner is not None:
                    return self._name_number(owner, attr, depth + 1)
            return None
        finally:
            self._numbers_active.discard(key)

    def _attribute_number(self, expr, scope, depth):
        base = self.value(expr.value, scope, depth)
        if base is None:
            return None
        if base.kind == MODULE:
            module = self.module(base.ref)
            owner = self.module_owner(module, expr.attr, depth)[0] \
                if module is not None else None
            return self._name_number(owner, expr.attr, depth) \
                if owner is not None else None
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
            owner = self.owner(scope, expr.id, depth)
            return self._sole_binding(owner, expr.id, depth) \
                if owner is not None else None
        if not isinstance(expr, ast.Attribute):
            return None
        base = self.value(expr.value, scope, depth)
        if base is None:
            return None
        if base.kind == MODULE:
            module = self.module(base.ref)
            owner = self.module_owner(module, expr.attr, depth)[0] \
                if module is not None else None
            return self._sole_binding(owner, expr.attr, depth) \
                if owner is not None else None
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
            owner = self.module_owner(module, attr, depth)[0] \
                if module is not None else None
            if owner is not None:
                return self._sole_binding(owner, attr, depth + 1)
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

    @contextlib.contextmanager
    def substituting(self, substitute):
        """Compute strings with some expressions standing for a value.

        :param substitute: (expression, scope) -> the text it stands for,
          or None to evaluate it as usual
        """
        previous, self._substitute = self._substitute, substitute
        try:
            yield
        finally:
            self._substitute = previous

    def _string(self, expr, scope, depth):
        if self._substitute is not None:
            text = self._substitute(expr, scope)
            if text is not None:
                return text
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
            owner = self.owner(scope, expr.id)
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
    """A number from two, by the rules and limits launch files have too."""
    if left is None or right is None:
        return None
    try:
        value = python_arithmetic.binary(op, left, right)
    except python_arithmetic.Refused:
        return None
    return value if isinstance(value, (int, float)) else None


def call_argument(call, spec):
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
