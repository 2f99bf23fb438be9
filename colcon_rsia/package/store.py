# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Summary files under the build base: paths, atomic writes, reading."""

from dataclasses import asdict
import hashlib
import json
import os

from colcon_rsia import safe_files
from colcon_rsia.model import PackageSummary
from colcon_rsia.model import WrapperSummary
from colcon_rsia.safe_files import display
from colcon_rsia.safe_files import max_file_bytes
from colcon_rsia.safe_files import read_bytes

RSIA_DIRNAME = 'rsia'
SUMMARY_FILENAME = 'summary.json'
# why the last analysis of a package failed (removed by the next success)
FAILURE_FILENAME = 'failure.json'
CACHE_DIRNAME = 'cache'
SUMMARY_SIZE_FACTOR = 8


def name_problem(name):
    """Why a package name cannot name a directory under the build base.

    Every path of a package's output is ``<build base>/<name>/…``: a name
    that is not one plain path component (``../../x``, ``a/b``, ``..``)
    would put it elsewhere. None when the name is fine.
    """
    if not name or name in ('.', '..') or '\0' in name or \
            any(s and s in name for s in (os.sep, os.altsep)):
        return (f"the package name '{display(name)}' is not a plain "
                'directory name: its results would be written outside the '
                'build base; skipped')
    return None


def summary_path(package_build_base):
    """Return the summary path of a package's build directory."""
    return os.path.join(package_build_base, RSIA_DIRNAME, SUMMARY_FILENAME)


def cache_dir(package_build_base):
    """Return the per-TU cache directory of a package's build directory."""
    return os.path.join(package_build_base, RSIA_DIRNAME, CACHE_DIRNAME)


def precompiled_dir(package_build_base):
    """Where the model mode's precompiled headers are kept.

    Beside the packages' build directories, shared by them all (they are
    the same for every package); no package is named with a leading dot.
    """
    return os.path.join(
        os.path.dirname(os.path.abspath(package_build_base)),
        '.' + RSIA_DIRNAME, 'precompiled')


def write_json_atomically(path, data):
    """Write JSON so that readers see the old file or the new, never half.

    A temp file in the same directory is renamed over the target; a build
    killed mid-write leaves at most a stray temp file.
    """
    write_text_atomically(
        path, json.dumps(data, indent=1, sort_keys=True) + '\n')


def write_text_atomically(path, text):
    r"""Write a text file whole or not at all (see write_json_atomically).

    Undecodable names (surrogate escapes) are written as ``\\udce9``
    rather than failing the write.
    """
    safe_files.write_text_atomically(path, text, errors='backslashreplace')


def write_summary(package_build_base, summary):
    """Store a package summary; return its path.

    Never a summary its reader rejects: node ids are made distinct first
    (:func:`distinct_node_ids`), and the data is checked by the reader's
    own :meth:`PackageSummary.from_dict` (a ValueError left is a bug, which
    the runner reports as the package's failure).
    """
    path = summary_path(package_build_base)
    distinct_node_ids(summary)
    data = summary.to_dict()
    PackageSummary.from_dict(data)
    write_json_atomically(path, data)
    try:
        os.unlink(_failure_path(package_build_base))
    except OSError:
        pass
    return path


# the kinds a launch file starts by their id (the plugin name): they keep it
_LAUNCHED_BY_ID = ('nodelet', 'component', 'plugin')


def distinct_node_ids(summary):
    """Give the nodes of a summary distinct ids (its reader requires them).

    One source built into two targets (an executable and, behind a
    preprocessor switch, a nodelet of the same name) makes two nodes of
    one id. The node a launch file names by its id (a nodelet, a
    component, a plugin) keeps it; the others become
    ``<id>/<node name>``, as the nodes of a multi-node executable are
    named, else ``<id>/<kind>``, with a diagnostic naming both.
    """
    taken = {node.id for node in summary.nodes}
    by_id = {}
    for node in summary.nodes:
        by_id.setdefault(node.id, []).append(node)
    for node_id, nodes in sorted(by_id.items()):
        if len(nodes) < 2:
            continue
        keeper = next((n for n in nodes if n.kind in _LAUNCHED_BY_ID),
                      nodes[0])
        for node in nodes:
            if node is keeper:
                continue
            suffix = node.name.strip('/') if node.name else node.kind
            new_id = f'{node_id}/{suffix}'
            number = 2
            while new_id in taken:
                new_id = f'{node_id}/{suffix}{number}'
                number += 1
            taken.add(new_id)
            node.id = new_id
            summary.diagnostics.append(
                f"node id '{node_id}' named two nodes, kinds {keeper.kind} "
                f'and {node.kind} (one source built into two targets?): '
                f"the {node.kind} is '{new_id}'")


def _failure_path(package_build_base):
    return os.path.join(package_build_base, RSIA_DIRNAME, FAILURE_FILENAME)


def write_failure(package_build_base, package, message):
    """Record that a package's analysis failed, and why."""
    write_json_atomically(_failure_path(package_build_base),
                          {'package': package, 'error': message})


def read_failure(package_build_base):
    """The message of the package's last failed analysis, or None."""
    try:
        with open(_failure_path(package_build_base), encoding='utf-8') as h:
            data = json.load(h)
        return str(data['error'])
    except (OSError, ValueError, KeyError, TypeError):
        return None


class SummaryError(RuntimeError):
    """A summary file that cannot be used."""


def read_summary(path):
    """Read one summary file.

    :raises SummaryError: with one sentence naming the file and the problem
    """
    try:
        # a summary lists every fact of a package: above a source's limit
        data = json.loads(read_bytes(
            path, limit=SUMMARY_SIZE_FACTOR * max_file_bytes()).decode('utf-8'))
    except FileNotFoundError:
        raise SummaryError(f"no summary at '{path}'")
    except RecursionError:
        raise SummaryError(
            f"corrupted summary '{path}' (nested too deeply); re-run "
            "'colcon rsia analyze' for its package")
    except (OSError, ValueError) as e:
        raise SummaryError(
            f"corrupted summary '{path}' ({e}); re-run "
            "'colcon rsia analyze' for its package")
    if not isinstance(data, dict):
        raise SummaryError(f"corrupted summary '{path}': not an object")
    try:
        return PackageSummary.from_dict(data)
    except ValueError as e:
        raise SummaryError(
            f"summary '{path}' cannot be used: {e}; re-run "
            "'colcon rsia analyze' for its package")


def find_summaries(build_base):
    """Return {package name: summary path} of every analysed package."""
    found = {}
    try:
        names = sorted(os.listdir(build_base))
    except OSError:
        return found
    for name in names:
        path = summary_path(os.path.join(build_base, name))
        if os.path.isfile(path):
            found[name] = path
    return found


def read_results(build_base, names):
    """What the last analysis of each named package left.

    :returns: ``(summaries, failures, not_analysed)``: the summaries read,
      ``{name: message}`` of the packages whose last analysis failed, and
      the names of those without a usable summary
    """
    summaries = []
    failures = {}
    not_analysed = []
    for name in names:
        package_build = os.path.join(build_base, name)
        failure = read_failure(package_build)
        if failure is not None:
            failures[name] = failure
            continue
        try:
            summaries.append(read_summary(summary_path(package_build)))
        except SummaryError:
            not_analysed.append(name)
    return summaries, failures, not_analysed


# --- the wrappers a package offers the packages analysed after it ---------

WRAPPERS_FILENAME = 'wrappers.json'
WRAPPERS_SCHEMA = 'colcon-rsia/wrappers@1'


def write_wrappers(package_build_base, package_path, wrappers):
    """Store the summaries of a package's wrapper functions (or none)."""
    path = os.path.join(package_build_base, RSIA_DIRNAME, WRAPPERS_FILENAME)
    if not wrappers:
        try:
            os.unlink(path)
        except OSError:
            pass
        return
    write_json_atomically(path, {
        'schema': WRAPPERS_SCHEMA, 'path': package_path,
        'wrappers': [asdict(w) for w in wrappers]})


def read_workspace_wrappers(package_build_base, package_dirs):
    """The wrapper summaries the workspace's other packages stored.

    Every package's output is a sibling of this one's under the build base;
    a file whose package is no longer in the workspace (``package_dirs``)
    or that cannot be read is left out: its calls give no facts, as before
    its package was analysed.
    """
    build_base = os.path.dirname(os.path.abspath(package_build_base))
    own = os.path.basename(os.path.abspath(package_build_base))
    wanted = {os.path.abspath(d) for d in package_dirs}
    found = []
    try:
        names = sorted(os.listdir(build_base))
    except OSError:
        return found
    for name in names:
        path = os.path.join(build_base, name, RSIA_DIRNAME, WRAPPERS_FILENAME)
        if name == own or not os.path.isfile(path):
            continue
        try:
            data = json.loads(read_bytes(path).decode('utf-8'))
            if data.get('schema') != WRAPPERS_SCHEMA or \
                    data.get('path') not in wanted:
                continue
            found.extend(WrapperSummary(**w) for w in data['wrappers'])
        except (OSError, ValueError, KeyError, TypeError, AttributeError,
                RecursionError):
            continue
    return found


def dependency_problems(package_build_base, dependencies):
    """Say which dependencies have no analysis of their sources here.

    A package's C++ analysis reads the wrappers of the workspace's other
    packages from its siblings under the build base
    (:func:`read_workspace_wrappers`); a dependency with no summary there,
    or one made from another source tree, offers none, and the calls into
    its libraries give no facts. (A summary without ``wrappers.json`` is a
    dependency with no wrappers: nothing is missing.)

    :param dependencies: ``(name, source directory)`` of the workspace's
      packages the package depends on, whose analysis may offer wrappers
    :returns: one diagnostic per dependency missing, by name
    """
    build_base = os.path.dirname(os.path.abspath(package_build_base))
    problems = []
    for name, path in sorted(dependencies):
        if name_problem(name):
            continue
        package_build = os.path.join(build_base, name)
        if _summary_source(summary_path(package_build)) == \
                os.path.abspath(path):
            continue
        failure = read_failure(package_build)
        if failure is not None:
            problems.append(
                f'the analysis of the dependency {name} failed ({failure}): '
                'calls into its libraries give no facts here')
        else:
            problems.append(
                f'the dependency {name} has no analysis of its sources in '
                'this build base: calls into its libraries give no facts '
                'here. Analyse it in the same run (e.g. with '
                "--packages-up-to) or merge its results in first ('colcon "
                "rsia merge'), then analyse this package again")
    return problems


# summary path -> ((modification time, size), its source directory): a
# package's dependencies are asked about for every package depending on them
_summary_sources = {}


def _summary_source(path):
    """The source directory a usable summary names, or None."""
    try:
        stat = os.stat(path)
    except OSError:
        return None
    key = (stat.st_mtime_ns, stat.st_size)
    known = _summary_sources.get(path)
    if known is not None and known[0] == key:
        return known[1]
    try:
        source = os.path.abspath(read_summary(path).path)
    except SummaryError:
        source = None
    _summary_sources[path] = (key, source)
    return source


def wrappers_digest(wrappers):
    """A digest of wrapper summaries: the units calling them depend on it."""
    if not wrappers:
        return None
    return hashlib.sha1(json.dumps(
        sorted((asdict(w) for w in wrappers), key=lambda w: w['usr']),
        sort_keys=True).encode()).hexdigest()
