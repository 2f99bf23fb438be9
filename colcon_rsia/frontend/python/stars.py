# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Names a module takes through ``from X import *``.

Part of the Python front end (see :mod:`colcon_rsia.frontend.python`):
mixed into the evaluation (:class:`colcon_rsia.frontend.python.values.
Project`). A name no scope of a module binds may come from a star import:
from a module of the package, the names of its ``__all__`` (else its
public names), the last star import that has the name winning, as when
run; from an outside module, the APIs of :mod:`python_api`.
"""

import ast

from colcon_rsia.frontend import python_api
from colcon_rsia.frontend.python.scopes import lookup

# how deep the evaluation of one expression may go (names bound to names…)
MAX_DEPTH = 32


class StarImports:
    """The names a module takes through its star imports.

    Mixed into a class with ``module()``, ``package_modules``,
    ``name_value()``, ``external()`` and a ``_stars_active`` set.
    """

    def owner(self, scope, name, depth=0):
        """The scope that binds a name read in `scope`, or None.

        Where the scope's own code binds it (:func:`lookup`), else the
        package module a ``from X import *`` of its module takes it from.
        """
        owner = lookup(scope, name)
        if owner is None:
            owner, _ = self.star_source(scope.module, name, depth)
        return owner

    def module_owner(self, module, name, depth=0):
        """(scope, None) of the module that binds ``module.name``.

        The module itself, else what its star imports give (see
        :meth:`star_source`); (None, None) when neither binds it.
        """
        if name in module.scope.bindings:
            return module.scope, None
        return self.star_source(module, name, depth)

    def star_source(self, module, name, depth=0):
        """Where ``from X import *`` of a module takes a name from.

        (module scope, None): a package module that binds it (its
        ``__all__``, else its public names); (None, dotted name): an API
        of :mod:`python_api` an outside module X has; (None, None): none.
        The last star import that has the name wins, as when run.
        """
        return next(self._star_sources(module, name, depth), (None, None))

    def _star_sources(self, module, name, depth):
        """The star imports that bind a name, the one that wins first."""
        if depth > MAX_DEPTH:
            return
        for base in reversed(module.star_imports):
            if base not in self.package_modules:
                dotted = python_api.canonical(f'{base}.{name}')
                if python_api.lookup(dotted) is not None or \
                        dotted in python_api.DURATIONS:
                    yield None, dotted
                continue
            other = self.module(base)
            if other is None or other is module or \
                    not _exports(other, name):
                continue
            if name in other.scope.bindings:
                yield other.scope, None
            else:
                yield from self._star_sources(other, name, depth + 1)

    def _star_value(self, module, name, depth):
        """The value of a name a module takes through its star imports.

        A module re-exporting a name it imports from the package that
        star-imports it (``from package import Name`` in a module whose
        names the package's ``__init__.py`` star-imports) leads back to
        the name being evaluated: that candidate is passed over for the
        next one, as the order of the imports makes it when run.
        """
        key = (module.name, name)
        if key in self._stars_active or depth > MAX_DEPTH:
            return None
        self._stars_active.add(key)
        try:
            for owner, dotted in self._star_sources(module, name, depth):
                if dotted is not None:
                    return self.external(dotted)
                value = self.name_value(owner, name, depth + 1)
                if value is not None:
                    return value
            return None
        finally:
            self._stars_active.discard(key)


def _exports(module, name):
    """Whether ``from module import *`` binds `name`.

    The names of its ``__all__`` when that is a list of strings, else its
    names that do not start with ``_``.
    """
    listed = set()
    for kind, payload, _ in module.scope.bindings.get('__all__', ()):
        if kind != 'assign' or not isinstance(payload, (ast.List, ast.Tuple)):
            return not name.startswith('_')
        listed.update(e.value for e in payload.elts
                      if isinstance(e, ast.Constant))
    if module.scope.bindings.get('__all__'):
        return name in listed
    return not name.startswith('_')
