# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Analyse one package: sources -> facts -> nodes -> labels -> summary.

The event handler and ``colcon rsia analyze`` both call
:func:`analyze_package`.
"""

import functools
import glob
import os
import shutil
import time

from colcon_rsia import __version__
from colcon_rsia import safe_files
from colcon_rsia.environment_variables import CXX_STD_ENVIRONMENT_VARIABLE
from colcon_rsia.frontend.compile_db import COMPILE_DB_FILENAME
from colcon_rsia.frontend.compile_db import CompileDatabaseError
from colcon_rsia.frontend.compile_db import CompileEntry
from colcon_rsia.frontend.compile_db import find_resource_dir
from colcon_rsia.frontend.compile_db import load_compile_database
from colcon_rsia.frontend.compile_db import RESOURCE_DIR_HINT
from colcon_rsia.frontend.ros_api import MAIN_FUNCTION
from colcon_rsia.package import build_paths
from colcon_rsia.package import coverage
from colcon_rsia.package import plugin_hosts
from colcon_rsia.package import shared_cache
from colcon_rsia.package import workers
from colcon_rsia.package.assembly import build_node
from colcon_rsia.package.assembly import executable_nodes
from colcon_rsia.package.cache import unit_cache_file
from colcon_rsia.package.cache import write_cached_facts
from colcon_rsia.package.call_sites import CXX_SOURCE_EXTENSIONS
from colcon_rsia.package.node_facts import merge_facts
from colcon_rsia.package.node_facts import select_functions
from colcon_rsia.package.nodes import find_components
from colcon_rsia.package.nodes import find_executables
from colcon_rsia.package.nodes import find_nodelets
from colcon_rsia.package.nodes import find_plugins
from colcon_rsia.package.nodes import skipped_executable
from colcon_rsia.package.nodes import target_naming
from colcon_rsia.package.nodes import TEXT_READER
from colcon_rsia.package.repair_gains import unrecorded_calls
from colcon_rsia.package.units import parse_units
from colcon_rsia.package.workers import check_stop
from colcon_rsia.summary import store
from colcon_rsia.summary import wrapper_store
from colcon_rsia.summary.coverage import Coverage
from colcon_rsia.summary.coverage import UnitCoverage
from colcon_rsia.summary.kinds import UNKNOWN_NAMESPACE
from colcon_rsia.summary.package_summary import PackageSummary
from colcon_rsia.summary.package_summary import Phases


class AnalysisError(RuntimeError):
    """An expected failure of one package's analysis (one clear sentence)."""


HEADER_MODES = ('model', 'exact')

REPAIR_WHEN_IT_PAYS = 'when-it-pays'
REPAIR_ALWAYS = 'always'
REPAIR_POLICIES = (REPAIR_WHEN_IT_PAYS, REPAIR_ALWAYS)

DEFAULT_STD = 'c++17'

# directories whose sources are never a node's (tests, generated output)
SKIPPED_DIRECTORIES = frozenset({
    'test', 'tests', 'build', 'install', 'devel', 'log', 'CMakeFiles'})


def analyze_package(*, name, path, build_base, jobs=None, use_cache=True,
                    nothing_compiled=False, header_mode='exact',
                    workspace_package_dirs=(), extra_arguments=(),
                    repair=REPAIR_WHEN_IT_PAYS, write=True,
                    dependency_dirs=None):
    """Analyse a C++ package; store the summary.

    The translation units and their flags come from the package's compile
    database, or, when there is none (a package never built), from its
    sources with flags made up from the workspace (see
    :func:`synthesized_entries`).

    :param str name: the package name
    :param str path: the package source directory
    :param str build_base: the package's build directory
    :param int jobs: parallel parses, each in a worker process (default:
      the number of CPUs)
    :param bool use_cache: reuse facts of unchanged translation units
    :param bool nothing_compiled: the package compiles no translation unit
      (CMake wrote no compile database): summarise it with no nodes
    :param str header_mode: 'exact' parses with the headers the compiler
      used; 'model' with the tool's model headers of the ROS API and
      stand-ins for everything else (no ROS installation needed)
    :param workspace_package_dirs: source directories of every package of
      the workspace, whose headers the model mode keeps
    :param extra_arguments: more compiler arguments for every TU
    :param str repair: model mode: REPAIR_WHEN_IT_PAYS repairs a unit only
      when the AST lost some of its calls (the tokens have them);
      REPAIR_ALWAYS repairs every unit with errors in its own code (fewer
      parse errors, more parses)
    :param bool write: store the summary (a caller that adds to it first
      stores it itself)
    :param dependency_dirs: source directories of the workspace's packages
      this one depends on: only their wrappers are read (a package calls
      into no library it does not depend on), so that the facts, and the
      cache, do not depend on which other packages were analysed first.
      None: those of every package of ``workspace_package_dirs``
    :returns: the summary, also written to ``<build_base>/rsia/summary.json``
    :rtype: colcon_rsia.summary.package_summary.PackageSummary
    :raises AnalysisError: when the package cannot be analysed at all
    """
    if header_mode not in HEADER_MODES:
        raise AnalysisError(
            f"unknown header mode '{header_mode}' (one of "
            f"{', '.join(HEADER_MODES)})")
    try:
        timeout = workers.unit_timeout()
    except ValueError as e:
        raise AnalysisError(str(e)) from None
    started = time.monotonic()
    path = os.path.abspath(path)
    db_path = os.path.join(build_base, COMPILE_DB_FILENAME)
    if nothing_compiled:
        entries = []
    elif os.path.isfile(db_path):
        try:
            entries = load_compile_database(db_path)
        except CompileDatabaseError as e:
            raise AnalysisError(str(e)) from None
    else:
        entries = synthesized_entries(
            path, workspace_package_dirs=workspace_package_dirs,
            with_system_ros=header_mode == 'exact')
    entries = [e for e in entries if _inside(e.file, path)]
    for entry in entries:
        entry.arguments = list(entry.arguments) + list(extra_arguments)
    resource_dir = find_resource_dir()
    if resource_dir is None and entries:
        raise AnalysisError(RESOURCE_DIR_HINT)
    precompiled_dir = shared_repairs = plan_headers = reseed = None
    if header_mode == 'exact':
        from colcon_rsia.frontend.cpp import shared_headers
        # the system headers units share, compiled once for them
        precompiled_dir = build_paths.shared_headers_dir(build_base)
        plan_headers = shared_headers.plan
    if header_mode == 'model':
        entries = _model_entries(
            entries, path, workspace_package_dirs,
            os.path.join(build_base, store.RSIA_DIRNAME, 'stubs'))
        precompiled_dir = build_paths.precompiled_dir(build_base)
        if entries:
            from colcon_rsia.frontend.cpp.model_mode import recovery
            # made only when a unit is parsed: it reads the workspace's
            # sources, which a run whose units are all cached need not
            shared_repairs = functools.partial(
                recovery.workspace_repairs,
                build_paths.workspace_repairs_file(build_base),
                workspace_package_dirs)
            reseed = functools.partial(recovery.reseed, package_path=path)

    prepared_at = time.monotonic()
    try:
        shared = shared_cache.SharedCache.from_environment(
            package_path=path, build_base=build_base,
            workspace_package_dirs=workspace_package_dirs,
            resource_dir=resource_dir) if use_cache else None
    except ValueError as e:
        raise AnalysisError(str(e)) from None
    units, diagnostics = parse_units(
        entries, unit_facts=_unit_facts, package_path=path,
        resource_dir=resource_dir, precompiled_dir=precompiled_dir,
        cache=build_paths.cache_dir(build_base) if use_cache else None,
        jobs=jobs or workers.default_jobs(), timeout=timeout, repair=repair,
        shared=shared, shared_repairs=shared_repairs,
        plan_headers=plan_headers, reseed=reseed,
        wrappers=wrapper_store.read_workspace_wrappers(
            build_base, workspace_package_dirs if dependency_dirs is None
            else dependency_dirs))
    if plan_headers is not None:
        # a few tens of MB each, worth nothing to the next run (it parses
        # only what changed)
        shutil.rmtree(precompiled_dir, ignore_errors=True)
    parsed_at = time.monotonic()
    summary, not_built = build_summary(
        name=name, path=path, build_base=build_base, units=units,
        parsed={e.file for e in entries})
    summary.coverage = _coverage(path, units, summary.nodes, not_built)
    summary.header_mode = header_mode
    summary.diagnostics = diagnostics + summary.diagnostics + \
        _unknown_namespace_notes(summary.nodes)
    summary.seconds = round(time.monotonic() - started, 3)
    summary.phases = Phases(
        prepare=round(prepared_at - started, 3),
        parse=round(parsed_at - prepared_at, 3),
        assemble=round(time.monotonic() - parsed_at, 3))
    check_stop()
    if write:
        store.write_summary(build_base, summary)
    wrapper_store.write_wrappers(build_base, path, _exported_wrappers(units))
    return summary


def _exported_wrappers(units):
    """The package's wrapper summaries, once each (headers are shared)."""
    unique = {}
    for file in sorted(units):
        for wrapper in units[file].wrappers:
            unique.setdefault(wrapper.usr, wrapper)
    return [unique[usr] for usr in sorted(unique)]


def _unknown_namespace_notes(nodes):
    """One note per endpoint named relative to a namespace not known."""
    notes = []
    for node in nodes:
        for endpoint in node.publishers + node.subscribers:
            namespace = endpoint.namespace or ''
            if namespace.startswith(UNKNOWN_NAMESPACE) and \
                    not (endpoint.topic or '').startswith(('/', '~')):
                notes.append(
                    f'{endpoint.location}: note: {endpoint.topic!r} is '
                    f'relative to the NodeHandle namespace '
                    f'{namespace[len(UNKNOWN_NAMESPACE):]!r}, whose '
                    f'value the analysis does not know: not connected')
    return sorted(set(notes))


def _coverage(path, units, nodes, not_built=()):
    """The C++ part of a package's coverage (see coverage.py).

    :param not_built: the programs (files) no target of the package builds
    """
    return Coverage(
        units=[UnitCoverage(
            file=os.path.relpath(file, path), errors=unit.errors,
            package_errors=unit.package_errors,
            repair_rounds=unit.repair_rounds, lost_calls=unit.lost_calls,
            repairs=[[rule, kind, _relative(name, path)]
                     for rule, kind, name in unit.repairs])
               for file, unit in sorted(units.items())],
        call_sites=coverage.call_site_coverage(
            coverage.package_call_sites(path, python=False),
            nodes=nodes, units=list(units.values()),
            not_built={os.path.relpath(f, path) for f in not_built}))


def synthesized_entries(path, *, workspace_package_dirs=(),
                        with_system_ros=True):
    """Translation units and flags of a package that was never built.

    Every C++ source of the package (tests and build output aside), with
    the package's ``include/`` and source directories, the ``include/``
    directories of the workspace's packages, the package's directory and
    its ``src/``, and, for the exact mode, the ROS include directories
    installed on the machine.
    """
    std = os.environ.get(CXX_STD_ENVIRONMENT_VARIABLE.name, DEFAULT_STD)
    # the package's own include directories, also those of the libraries
    # it vendors (lib/<library>/include), which its CMake would add
    include_dirs = _own_include_dirs(path)
    include_dirs += [os.path.join(package, 'include')
                     for package in sorted(workspace_package_dirs)]
    # "subdir/header.hpp" relative to the package (include_directories(.)),
    # then to its src/ (target_include_directories(x PUBLIC src), which a
    # subdirectory's target includes from: example_rule/src/rule.cpp's
    # "switch_rule/base_switch_rule.hpp" is src/switch_rule/'s)
    include_dirs += [path, os.path.join(path, 'src')]
    if with_system_ros:
        include_dirs += sorted(glob.glob('/opt/ros/*/include'))
    include_dirs = [d for d in dict.fromkeys(include_dirs) if os.path.isdir(d)]
    entries = []
    for root, dirs, files in os.walk(path):
        dirs[:] = sorted(
            d for d in dirs
            if d not in SKIPPED_DIRECTORIES and not d.startswith('.'))
        # the source's directory, then those between it and the package
        # ("rule_helper/area.hpp" from rules/src/rule_helper/area.cpp, as a
        # subdirectory's CMake adds them: target_include_directories(x
        # src)), then the include directories above
        arguments = ['-x', 'c++', f'-std={std}']
        for directory in [root, *_directories_up_to(root, path),
                          *include_dirs]:
            arguments += ['-I', directory]
        for file in sorted(files):
            if file.endswith(CXX_SOURCE_EXTENSIONS):
                entries.append(CompileEntry(
                    file=os.path.join(root, file), directory=path,
                    arguments=list(arguments)))
    return entries


def _directories_up_to(directory, package):
    """The directories above ``directory``, below ``package``."""
    found = []
    parent = os.path.dirname(directory)
    while _inside(parent, package):
        found.append(parent)
        parent = os.path.dirname(parent)
    return found


def _own_include_dirs(path):
    found = []
    for root, dirs, _ in os.walk(path):
        dirs[:] = sorted(
            d for d in dirs
            if d not in SKIPPED_DIRECTORIES and not d.startswith('.'))
        if 'include' in dirs:
            found.append(os.path.join(root, 'include'))
            dirs.remove('include')
    return found or [os.path.join(path, 'include')]


def _model_entries(entries, path, workspace_package_dirs, stub_dir):
    from colcon_rsia.frontend.cpp.model_mode import prepare_model_arguments
    from colcon_rsia.frontend.cpp.model_mode import recovery
    from colcon_rsia.frontend.cpp.model_mode.include_scan import FileCache
    model_entries = []
    files = FileCache()
    for entry in entries:
        arguments = prepare_model_arguments(
            source=entry.file, arguments=entry.arguments,
            package_path=path,
            workspace_package_dirs=list(workspace_package_dirs),
            stub_dir=stub_dir, directory=entry.directory, files=files)
        # what clang's errors show missing is declared there (recovery/)
        header = recovery.repair_header(stub_dir, entry.file)
        recovery.ensure_repair_header(
            header, os.path.relpath(entry.file, path))
        arguments += ['-include', header]
        model_entries.append(CompileEntry(
            file=entry.file, directory=entry.directory, arguments=arguments))
    return model_entries


def _relative(path, directory):
    return os.path.relpath(path, directory) if _inside(path, directory) \
        else path


def _inside(file, directory):
    return os.path.abspath(file).startswith(directory.rstrip('/') + '/')


def _unit_facts(entry, package_path, resource_dir, cache, hidden=None, *,
                wrappers=(), wrappers_digest=None, precompiled_dir=None,
                repair=REPAIR_WHEN_IT_PAYS, shared=None, shared_repairs=None,
                package_headers=None, reseeded=False):
    """Facts of one TU, parsed (in a worker process: see workers.py).

    :param hidden: {file: why} of files libclang is given as empty
    :param wrappers: the other packages' wrapper summaries (parse_units),
      and ``wrappers_digest`` theirs (wrapper_store.wrappers_digest)
    :param shared: the shared_cache.SharedCache the facts are kept in too
    :param shared_repairs: the model mode's repairs every package's units
      share (recovery.workspace_repairs), or None
    :param package_headers: exact mode: {unit file: the system headers it
      shares with other units of its package} (shared_headers.plan); the
      PCH of them is kept in ``precompiled_dir``
    :param reseeded: the unit is parsed again, seeded with what its package
      learnt since (recovery.reseed): one more parse, as a repair round
    """
    hidden = hidden or {}
    relative = safe_files.display(os.path.relpath(entry.file, package_path))
    cache_file = None if cache is None else unit_cache_file(cache, entry)
    # imported here: libclang is needed only when something is parsed
    import clang.cindex as ci
    from colcon_rsia.frontend import cpp
    from colcon_rsia.frontend.clang_names import allow_undecodable_names
    allow_undecodable_names()
    from colcon_rsia.frontend.cpp.model_mode import precompiled
    from colcon_rsia.frontend.cpp.model_mode.recovery import parse_unit
    from colcon_rsia.frontend.cpp.wrappers import ExternalWrappers
    external = ExternalWrappers(wrappers) if wrappers else None
    # the files that failed the checks are seen by libclang as empty
    hidden_files = [(file, '') for file in sorted(
        set(hidden) | {os.path.realpath(h) for h in hidden})]
    # the files a precompiled header read are the unit's inputs too (the
    # unit's include list lacks them)
    pch_inputs = []
    if package_headers is None:
        pch = [precompiled.precompiled_header(
            precompiled_dir, entry.file, entry.arguments, resource_dir)
            if precompiled_dir else None]
    else:
        from colcon_rsia.frontend.cpp import shared_headers
        built = shared_headers.precompiled(
            precompiled_dir, package_headers[entry.file], entry.arguments,
            entry.directory, resource_dir) \
            if precompiled_dir and entry.file in package_headers else None
        pch = [None] if built is None else [built[0]]
        pch_inputs = [] if built is None else built[1]
    index = ci.Index.create()

    def parse(arguments, edited_files):
        def parse_with(arguments):
            return cpp.parse(
                index, file=entry.file, arguments=arguments,
                resource_dir=resource_dir, working_directory=entry.directory,
                unsaved_files=hidden_files + list(edited_files))
        if pch[0] is None:
            return parse_with(arguments)
        try:
            return parse_with(list(arguments) + ['-include-pch', pch[0]])
        except ci.TranslationUnitLoadError:
            # raises again when the unit itself is the problem
            tu = parse_with(arguments)
            if package_headers is None:
                precompiled.discard(pch[0])
            pch[0] = None
            return tu

    def facts_of(tu):
        return cpp.extract_facts(tu, package_path=package_path,
                                 source=relative, external_wrappers=external)
    try:
        parsed = parse_unit(
            index, entry, parse=parse, resource_dir=resource_dir,
            package_path=package_path, relative=relative, facts_of=facts_of,
            unrecorded=(lambda tu, facts: unrecorded_calls(
                tu, facts, package_path))
            if repair == REPAIR_WHEN_IT_PAYS else None,
            check_stop=check_stop, workspace_repairs=shared_repairs)
    except ci.TranslationUnitLoadError as e:
        return None, [f'{relative}: libclang could not parse it ({e})']
    tu, facts, rounds = parsed.tu, parsed.facts, parsed.rounds
    facts.repairs = sorted(
        [rule, kind, name] for (kind, name), rule in parsed.repairs.items())
    facts.diagnostics = [
        f'{relative}: parse error: {m}' for m in cpp.parse_diagnostics(tu)
    ] + facts.diagnostics
    errors = cpp.error_diagnostics(tu)
    facts.errors = len(errors)
    # (an error with no place, a force-included header not found say,
    # stops the parse before the package's code: it counts)
    facts.package_errors = sum(
        1 for e in errors if not e[1] or _inside(e[1], package_path))
    facts.repair_rounds = rounds + reseeded
    # (without an error in the package's code the parse lost nothing; the
    # repair rounds counted it already when they ran)
    facts.lost_calls = 0 if not facts.package_errors else \
        parsed.lost_calls if parsed.lost_calls is not None else \
        unrecorded_calls(tu, facts, package_path)
    includes = sorted({
        os.path.abspath(i.include.name) for i in tu.get_includes()
        if i.include is not None} | set(pch_inputs if pch[0] else ()))
    facts.diagnostics += [
        f"{relative}: includes '{safe_files.display(_relative(h, package_path))}'"
        f', which {reason}' for h, reason in sorted(hidden.items())
        if h in includes or os.path.realpath(h) in includes]
    facts.files = [relative] + [
        os.path.relpath(i, package_path) for i in includes
        if _inside(i, package_path)]
    if cache_file is not None:
        # stand-ins only grow as other TUs are prepared: not an input
        inputs = [i for i in includes if f'/{store.RSIA_DIRNAME}/stubs/' not in i]
        write_cached_facts(cache_file, entry, [entry.file] + inputs, facts,
                           wrappers_digest)
        if shared is not None:
            shared.store(entry, wrappers_digest, inputs, facts)
    return facts, list(facts.diagnostics)


def build_summary(*, name, path, build_base, units, parsed=None):
    """Turn the facts of a package's TUs into its labelled nodes.

    Every executable has its own ``main`` (and may reuse free function
    names), and those share USRs across executables: a node's facts are
    those of its own TUs plus the package's library TUs, never another
    executable's.

    Returns (the summary, {the files of the programs that no target the
    package's CMake code names builds}).
    """
    not_built = set()
    summary = PackageSummary(
        package=name, path=path, tool_version=__version__)
    read_by = []
    executables = find_executables(package_path=path, build_base=build_base,
                                   diagnostics=summary.diagnostics,
                                   read_by=read_by)
    executable_sources = {s for sources in executables.values()
                          for s in sources}
    unreadable = safe_files.unreadable_files(path, ['CMakeLists.txt'])
    summary.diagnostics += unreadable
    # what the CMake code says is known only when there is CMake code read
    targets_known = not unreadable and os.path.isfile(
        os.path.join(path, 'CMakeLists.txt'))
    # a unit with its own main() is a program, never library code that
    # every executable would take in. One no target builds is no node of
    # the running system (an example, a tool the build leaves out): it
    # gets a note. Without CMake code to read it is a node named after its
    # file (a guess, said so)
    for file, unit in sorted(units.items()):
        if file in executable_sources or not _defines_main(unit):
            continue
        relative = os.path.relpath(file, path)
        # CMake could not run: a command of a module the text reader does
        # not know may build it (a guess, said so)
        target = target_naming(path, file) \
            if targets_known and read_by == [TEXT_READER] else None
        if target is not None and target not in executables:
            executables[target] = [file]
            executable_sources.add(file)
            summary.diagnostics.append(
                f'{relative}: note: defines main() and CMakeLists.txt names '
                f"it in a command CMake could not run here: node '{target}' "
                "named after that command's first argument")
            continue
        if targets_known:
            executable_sources.add(file)
            not_built.add(file)
            summary.diagnostics.append(
                f'{relative}: note: defines main() but no executable of '
                'CMakeLists.txt builds it: not a node')
            continue
        stem = os.path.splitext(os.path.basename(file))[0]
        if stem not in executables:
            executables[stem] = [file]
            executable_sources.add(file)
            why = 'CMakeLists.txt cannot be read' if unreadable \
                else 'the package has no CMakeLists.txt'
            summary.diagnostics.append(
                f"{relative}: note: defines main() but {why}: node '{stem}' "
                'named after the file')
    library = [u for f, u in units.items() if f not in executable_sources]
    library_files = {unit.source for unit in library}
    # every unit: a nodelet's or plugin's class may call code its library
    # shares with an executable (one source built into both targets)
    merged_all = merge_facts(units.values())
    exported = merged_all.plugin_exports
    components = find_components(package_path=path, exported_classes=exported,
                                 build_base=build_base)
    # component classes an executable of the package instantiates: the
    # executable is that node (one node, one id)
    wrapped = set()
    for executable, sources in sorted(executables.items()):
        own = [units[s] for s in sources if s in units]
        if not own:
            summary.diagnostics.append(skipped_executable(
                executable, sources, package_path=path, build_base=build_base,
                parsed=set(sources) if parsed is None else parsed,
                skipped_directories=SKIPPED_DIRECTORIES))
            continue
        seeds = {f.id for unit in own for f in unit.functions}
        merged = merge_facts(own + library)
        classes = _instantiated(merged, seeds, set(components.values()))
        wraps = classes.pop() if len(classes) == 1 else None
        if wraps is not None:
            # the component's methods all run, as they would in a
            # container: also those only its base calls (virtual ones)
            hierarchy = _class_and_bases(wraps, merged)
            seeds |= {f.id for f in merged.functions
                      if f.name.rsplit('::', 1)[0] in hierarchy}
        nodes = executable_nodes(
            name, executable, sources, path, merged, seeds,
            library_files=library_files)
        if wraps is not None and len(nodes) == 1:
            nodes[0].plugin_class = wraps
            wrapped.add(wraps)
        summary.nodes.extend(nodes)
    plugins = [
        (plugin, class_name, 'nodelet') for plugin, class_name in sorted(
            find_nodelets(package_path=path,
                          exported_classes=exported).items())]
    plugins += [
        (executable, class_name, 'component')
        for executable, class_name in sorted(components.items())
        if class_name not in wrapped]
    # a nodelet or component runs its class's methods (and its package
    # bases', through typedefs too) and what they call, in any unit (never
    # another executable's main: no method calls it)
    for plugin, class_name, kind in plugins:
        hierarchy = _class_and_bases(class_name, merged_all)
        prefixes = tuple(c + '::' for c in hierarchy)
        seeds = {f.id for f in merged_all.functions
                 if f.name.startswith(prefixes)}
        node = build_node(
            name, plugin.split('/')[-1], kind,
            _sources_of(path, merged_all, seeds), path, merged_all,
            seeds, node_id=plugin if '/' in plugin else f'{name}/{plugin}',
            hierarchy=hierarchy)
        node.plugin_class = class_name
        if not seeds:
            summary.diagnostics.append(
                f"{kind} '{node.id}': no method of {class_name} in the "
                'units analysed (behind a preprocessor switch of its '
                'target?): it has no facts')
        summary.nodes.append(node)
    summary.nodes.extend(_plugin_nodes(name, path, merged_all, exported))
    return summary, not_built


def _plugin_nodes(package, path, merged, exported):
    """The package's pluginlib classes that a host loads, as nodes.

    A plugin runs the methods of its class (and of the package classes it
    derives from) and what they call; its host calls them (see
    :mod:`colcon_rsia.package.plugin_hosts`). A plugin of a base no host
    of the table has is kept only when it makes endpoints (a transmission
    loader is no node).
    """
    found = find_plugins(package_path=path, exported_classes=exported)
    shorts = [class_name.split('::')[-1] for class_name, _ in found.values()]
    nodes = []
    for plugin, (class_name, base) in sorted(found.items()):
        classes = _class_and_bases(class_name, merged)
        host = plugin_hosts.host_of(base)
        methods = [f for f in merged.functions
                   if f.name.rsplit('::', 1)[0] in classes]
        seeds = {f.id for f in methods}
        host_roots = {}
        private = set()
        for function in methods:
            method = function.name.split('::')[-1]
            kind = plugin_hosts.root_kind(host, method)
            if kind is not None:
                host_roots[function.id] = kind
            if host is not None and method == host.private_handle_of and \
                    function.params:
                private.add(function.params[-1])
        short = class_name.split('::')[-1]
        if '/' not in plugin:
            plugin = short if shorts.count(short) == 1 else class_name
        node = build_node(
            package, plugin.split('/')[-1], 'plugin',
            _sources_of(path, merged, seeds), path, merged, seeds,
            node_id=plugin if '/' in plugin else f'{package}/{plugin}',
            host=host, host_roots=host_roots, private_handles=private,
            hierarchy=classes)
        node.base_class = base
        node.plugin_class = class_name
        if host is None and not (node.publishers or node.subscribers or
                                 node.timers or node.services or
                                 node.actions):
            continue
        nodes.append(node)
    return nodes


def _instantiated(merged, seeds, classes):
    """The classes of `classes` whose constructor the seeds reach."""
    reached = select_functions(merged, seeds)
    found = set()
    for function in merged.functions:
        if function.id in reached:
            owner, _, method = function.name.rpartition('::')
            if owner in classes and method == owner.split('::')[-1]:
                found.add(owner)
    return found


def _class_and_bases(class_name, merged):
    """A class's qualified name and its package bases', aliases followed."""
    aliases = dict(map(tuple, merged.class_aliases))
    bases = {}
    for derived, base in merged.class_bases:
        bases.setdefault(derived, set()).add(base)
    found = set()
    todo = [class_name]
    while todo:
        current = todo.pop()
        # an alias of an alias ends; a cycle cannot loop
        for _ in range(8):
            if current not in aliases:
                break
            current = aliases[current]
        if current in found:
            continue
        found.add(current)
        todo.extend(bases.get(current, ()))
    return found


def _sources_of(path, merged, seeds):
    return sorted({
        os.path.join(path, f.location.rsplit(':', 1)[0])
        for f in merged.functions if f.id in seeds})


def _defines_main(unit):
    return any(f.name == MAIN_FUNCTION and f.class_id is None
               for f in unit.functions)
