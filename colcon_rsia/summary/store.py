# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The summaries under the build base: where they are, writing, reading.

``<build base>/<pkg>/rsia/summary.json`` holds a package's summary, and
``failure.json`` beside it why its last analysis failed.
"""

import json
import os

from colcon_rsia.safe_files import max_file_bytes
from colcon_rsia.safe_files import read_bytes
from colcon_rsia.safe_files import write_json_atomically
from colcon_rsia.summary.package_summary import PackageSummary

RSIA_DIRNAME = 'rsia'
SUMMARY_FILENAME = 'summary.json'
# why the last analysis of a package failed (removed by the next success)
FAILURE_FILENAME = 'failure.json'
SUMMARY_SIZE_FACTOR = 8


def summary_path(package_build_base):
    """Return the summary path of a package's build directory."""
    return os.path.join(package_build_base, RSIA_DIRNAME, SUMMARY_FILENAME)


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
