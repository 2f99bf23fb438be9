# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Endpoints the package's helper functions and classes make per call.

Part of the Python front end (see :mod:`colcon_rsia.frontend.python`):
mixed into the walk (:mod:`colcon_rsia.frontend.python.walk`).

The Python counterpart of the C++ wrappers
(:mod:`colcon_rsia.frontend.cpp.wrappers`), for the package's own code: a
helper class or function that makes a publisher or a subscription from a
parameter (``Monitor(node, '/api/state')`` whose ``__init__`` calls
``node.create_subscription(T, topic_name, self.callback, 1)``, also
through ``self.topic = topic_name`` and in another method of the class,
or ``f'{ns}/odom'`` from a parameter ``ns``) is one endpoint per call,
named by the call's arguments (or the parameters' defaults). Each is the
endpoint the helper's code makes (its function, location, handle,
callback and message type), with the name the call gives: the package
analysis keeps these and drops the helper's unnamed one
(``node_facts._most_resolved``). Calls whose arguments give no name add
nothing: the helper's endpoint stays, unnamed (when other calls of the
same node give a name, that one is dropped too: the name is not known).
"""

import ast

from colcon_rsia.frontend import fact_builder
from colcon_rsia.frontend import recorder
from colcon_rsia.frontend import ros_api
from colcon_rsia.frontend.facts import PublisherFact
from colcon_rsia.frontend.python.scopes import lookup
from colcon_rsia.frontend.python.scopes import region
from colcon_rsia.frontend.python.values import EXT

# the roles of the endpoints a helper may make from its parameters
ENDPOINT_ROLES = frozenset({ros_api.PUBLISHER, ros_api.SUBSCRIBER})


class Helpers:
    """Endpoints named by the arguments of a call of a package helper."""

    def _helper_endpoints(self, function, call, context, offset):
        """Record the endpoints `function` makes, named by `call`.

        :param function: the scope of the package function called (a
          class's ``__init__`` for an instantiation)
        :param offset: 1 when the call passes the object first (a method
          called through its class)
        """
        sites = self._endpoint_sites(function)
        if not sites:
            return
        values = self._argument_texts(function, call, context, offset)
        if not values:
            return
        used = []

        def substitute(expr, scope):
            if isinstance(expr, ast.Name) and expr.id in values and \
                    lookup(scope, expr.id) is function:
                used.append(expr.id)
                return values[expr.id]
            return None

        # a message type passed as a parameter: the class the call gives
        types = {}
        for name, (expr, scope) in self._arguments(
                function, call, context, offset, defaults=False).items():
            value = self.project.value(expr, scope)
            if value is not None and value.kind == EXT:
                types[name] = self._msg_type(expr, context)
        for scope, site in sites:
            facts = fact_builder.unit_facts(self.facts.source)
            replay = type(self)(self.project, scope.module, facts)
            del used[:]
            with self.project.substituting(substitute):
                replay._call(site, recorder.Context(scope.id, scope=scope))
            if not used:
                continue  # the name does not come from the call
            for fact in facts.publishers + facts.subscribers:
                if not fact.topic_is_literal:
                    continue
                fact.msg_type = types.get(fact.msg_type, fact.msg_type)
                (self.facts.publishers if isinstance(
                    fact, PublisherFact) else
                 self.facts.subscribers).append(fact)

    def _endpoint_sites(self, function):
        """[(scope, call)] of the publishers and subscriptions it may make.

        Those of the function, and of every method of its class (and the
        package's base classes): a parameter kept in an attribute may name
        an endpoint made in another method.
        """
        cache = self._endpoint_site_cache
        if function.id in cache:
            return cache[function.id]
        scopes = [function]
        if function.cls is not None:
            for cls in self.project.mro(function.cls)[0]:
                scopes += [m for m in cls.methods.values()
                           if m is not function]
        sites = []
        for scope in scopes:
            body = [scope.node.body] if scope.kind == 'lambda' \
                else scope.node.body
            for node in region(body):
                if not isinstance(node, ast.Call):
                    continue
                _, api = self._api_of(
                    node, self.project.value(node.func, scope))
                if api is not None and api.role in ENDPOINT_ROLES and \
                        not api.implicit_topics:
                    sites.append((scope, node))
        cache[function.id] = sites
        return sites

    def _argument_texts(self, function, call, context, offset):
        """{parameter: text} of the parameters a call gives known values.

        A string or a number given, else the parameter's default.
        """
        texts = {}
        for name, (expr, scope) in self._arguments(
                function, call, context, offset).items():
            text = self.project.string(expr, scope)
            if text is None:
                number = self.project.number(expr, scope)
                text = str(number) if number is not None else None
            if text is not None:
                texts[name] = text
        return texts

    def _arguments(self, function, call, context, offset, defaults=True):
        """{parameter: (expression, scope)} a call gives its parameters.

        With `defaults`, the defaults of those it does not give.
        """
        params = function.params
        given = {}
        for index, argument in enumerate(call.args):
            if isinstance(argument, ast.Starred):
                break
            position = index - offset
            if 0 <= position < len(params):
                given[params[position]] = (argument, context.scope)
        for keyword in call.keywords:
            if keyword.arg in params:
                given[keyword.arg] = (keyword.value, context.scope)
        node = function.node
        if defaults and isinstance(
                node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            # defaults run where the function is defined
            positional = node.args.posonlyargs + node.args.args
            written = dict(zip(
                [a.arg for a in positional[len(positional) -
                                           len(node.args.defaults):]],
                node.args.defaults))
            written.update(
                (a.arg, d) for a, d in zip(node.args.kwonlyargs,
                                           node.args.kw_defaults)
                if d is not None)
            for name, default in written.items():
                if name in params and name not in given:
                    given[name] = (default, function.parent)
        return given
