# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Analyse one package's Python nodes: modules -> facts -> nodes -> summary.

The Python counterpart of :func:`colcon_rsia.package.analysis.analyze_package`:
the same facts (:class:`colcon_rsia.frontend.facts.TuFacts`, one per module, from
:mod:`colcon_rsia.frontend.python`), the same node selection and labelling
(:func:`colcon_rsia.package.assembly.build_node`), the same summary.
Nothing is built, imported or run: the sources are parsed where they are.

A node runs the functions of its entry module (a script's module body, or
the module of a ``console_scripts`` entry point) and whatever they call or
register in the package's other modules. Its roots are those of the C++
analysis plus the entry module's body and the entry function, both of
kind ``main``.

A module that cannot be parsed (a syntax error, text that is not UTF-8)
gets one diagnostic; a node whose entry module it is is not analysed, and
the other nodes are.
"""

import os
import time

from colcon_rsia import __version__
from colcon_rsia.frontend.python import extract_python_facts
from colcon_rsia.frontend.python import MODULE_FUNCTION
from colcon_rsia.package import coverage
from colcon_rsia.package.assembly import build_node
from colcon_rsia.package.node_facts import merge_facts
from colcon_rsia.package.python_nodes import find_python_nodes
from colcon_rsia.summary import store
from colcon_rsia.summary.coverage import Coverage
from colcon_rsia.summary.kinds import ROOT_MAIN
from colcon_rsia.summary.nodes import Root
from colcon_rsia.summary.package_summary import PackageSummary
from colcon_rsia.summary.package_summary import Phases


def analyze_python_package(*, name, path, build_base):
    """Analyse the Python nodes of a package; store the summary.

    :param str name: the package name
    :param str path: the package source directory
    :param str build_base: the package's build directory
    :returns: the summary, also written to ``<build_base>/rsia/summary.json``
    :rtype: colcon_rsia.summary.package_summary.PackageSummary
    """
    started = time.monotonic()
    summary = build_python_summary(name=name, path=path)
    summary.seconds = round(time.monotonic() - started, 3)
    summary.phases = Phases(python=summary.seconds)
    store.write_summary(build_base, summary)
    return summary


def build_python_summary(*, name, path):
    """The summary of a package's Python nodes (not written anywhere)."""
    path = os.path.abspath(path)
    summary = PackageSummary(
        package=name, path=path, tool_version=__version__)
    layout = find_python_nodes(path)
    summary.diagnostics.extend(layout.problems)
    units, failures = parse_modules(
        layout.modules, path, [n.module for n in layout.nodes])
    not_analysed = {}
    for spec in sorted(layout.nodes, key=lambda n: n.executable):
        unit = units.get(spec.module)
        if unit is None:
            not_analysed.setdefault(spec.module, []).append(spec.executable)
            continue
        entries = {f'{spec.module}:{MODULE_FUNCTION}'}
        if spec.function:
            entry = f'{spec.module}:{spec.function}'
            if entry not in {f.id for f in unit.functions}:
                summary.diagnostics.append(
                    f"executable '{spec.executable}': entry function "
                    f"'{spec.function}' not found in {unit.source}")
            entries.add(entry)
        if not spec.installed:
            summary.diagnostics.append(
                f'{os.path.relpath(spec.path, path)}: note: not installed; '
                f"analysed as the node '{spec.executable}' run from the "
                'source tree')
        seeds = {f.id for f in unit.functions}
        # only the modules the node loads: a subclass another node imports
        # must not add its overrides to this one
        merged = merge_facts(
            units[m] for m in sorted(loaded_modules(spec.module, units)))
        node = build_node(name, spec.executable, 'executable', [spec.path],
                          path, merged, seeds)
        _entry_roots(node, unit, entries)
        summary.nodes.append(node)
    # what an analysed module lost (a statement nested too deeply)
    for module in sorted(units):
        summary.diagnostics += units[module].diagnostics
    summary.diagnostics.extend(_parameter_notes(summary.nodes))
    for module in sorted(failures, key=lambda m: failures[m]):
        line = failures[module]
        executables = not_analysed.get(module)
        if executables:
            line += '; not analysed: ' + ', '.join(
                f"node '{e}'" for e in executables)
        summary.diagnostics.append(line)
    # a module no node loads (a plugin of rqt, a library of another
    # package's scripts) is not this package's nodes' code
    summary.coverage = Coverage(
        call_sites=coverage.call_site_coverage(
            coverage.package_call_sites(path, python=True),
            nodes=summary.nodes, units=list(units.values())))
    return summary


def _parameter_notes(nodes):
    """One note per topic taken from a parameter that has no default.

    ``rospy.get_param('topic')``, ``self.get_parameter('topic').value``
    of a parameter declared nowhere with a value: the name is the value a
    launch file gives the parameter; without one it is not known (the
    graph gives it no name and connects it to nothing).
    """
    notes = set()
    for node in nodes:
        for endpoint in node.publishers + node.subscribers:
            param = endpoint.topic_param
            if endpoint.topic_is_literal or param is None or \
                    param.default is not None:
                continue
            name = param.name if param.namespace != '~' \
                else f'~{param.name}'
            notes.add(
                f'{endpoint.location}: note: the topic {endpoint.topic!r} '
                f'is the value of the parameter {name!r}, which has no '
                f'default: not known unless a launch file sets it')
    return sorted(notes)


def parse_modules(modules, package_path, entry_modules):
    """Facts of the entry modules and of the package modules they use.

    :param dict modules: {module name: file} of the package
    :returns: ({module: facts}, {module: diagnostic of a module that could
      not be parsed})
    """
    units = {}
    failures = {}
    todo = list(entry_modules)
    seen = set()
    while todo:
        module = todo.pop(0)
        if module in seen or module not in modules:
            continue
        seen.add(module)
        facts = extract_python_facts(
            modules[module], package_path=package_path, module_name=module,
            package_modules=modules)
        if not facts.functions:
            failures[module] = '; '.join(facts.diagnostics) or \
                f'{facts.source}: not analysed'
            continue
        units[module] = facts
        todo.extend(sorted(m for m in _used_modules(facts)
                           if m in modules and m not in seen))
    return units, failures


def _used_modules(facts):
    """The modules whose functions a module's code calls or imports."""
    used = set()
    for call in facts.calls:
        for function in (call.caller, call.callee):
            module, _, _ = function.partition(':')
            used.add(module)
    return used


def loaded_modules(entry, units):
    """The entry module and the package modules it uses, transitively."""
    loaded = set()
    todo = [entry]
    while todo:
        module = todo.pop()
        if module in loaded or module not in units:
            continue
        loaded.add(module)
        todo.extend(_used_modules(units[module]) - loaded)
    return loaded


def _entry_roots(node, unit, entries):
    """The entry module's body and entry function are ``main`` roots."""
    wanted = {(f.name, f.location) for f in unit.functions if f.id in entries}
    present = set()
    for root in node.roots:
        if (root.function, root.location) in wanted:
            root.kind = ROOT_MAIN
            present.add((root.function, root.location))
    for function, location in sorted(wanted - present):
        # called by the module body here, but run by the entry point too
        node.roots.append(Root(function, ROOT_MAIN, location))
    node.roots.sort(key=lambda r: (r.location, r.function))
