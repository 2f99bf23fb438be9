# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Merge the analysis results of several build bases into one.

A large workspace is analysed in CI by several jobs (shards), each into a
build base of its own; the queries read one build base. What a package's
analysis leaves there is at most three files under ``<pkg>/rsia/``: its
summary (what every query reads), the failure of its last analysis (the
queries call the summary stale, ``problems`` and ``coverage`` report it)
and the wrappers it offers the packages analysed after it. They are
merged together or not at all: a package's files stay those of one
analysis.

The rules (docs/usage.md, ``colcon rsia merge``):

- a package in one shard only: its files replace those of the target;
- a package in several shards: merged once when the analyses are the
  same (all but the time they took, ``seconds`` and ``phases``); when they differ, it is
  a conflict, the package is not merged and the target keeps what it had.
  A build base carries no reliable time (an artifact download resets
  modification times), so there is no "newer" to keep;
- a file this version cannot read (another schema version, corrupt JSON,
  a summary its reader rejects) is one message; the package is not merged,
  the source is left as it is, and every other package is merged.
"""

from dataclasses import dataclass
from dataclasses import field
import json
import os
from typing import Dict
from typing import List

from colcon_rsia.package import build_paths
from colcon_rsia.safe_files import display
from colcon_rsia.safe_files import max_file_bytes
from colcon_rsia.safe_files import read_bytes
from colcon_rsia.safe_files import write_text_atomically
from colcon_rsia.summary import store
from colcon_rsia.summary import wrapper_store
from colcon_rsia.summary.package_summary import PackageSummary
from colcon_rsia.summary.package_summary import SUMMARY_SCHEMA
from colcon_rsia.summary.wrapper_store import WrapperSummary

# the files of one package's analysis, in the order they are written
RESULT_FILES = (store.SUMMARY_FILENAME, store.FAILURE_FILENAME,
                wrapper_store.WRAPPERS_FILENAME)
# what two analyses of the same sources may differ in
VOLATILE_SUMMARY_FIELDS = ('seconds', 'phases')


@dataclass
class PackageResult:
    """What one build base holds of one package's analysis."""

    package: str
    build_base: str
    # file name -> its text, as read
    texts: Dict[str, str] = field(default_factory=dict)
    # file name -> its data without what two equal analyses differ in
    comparable: Dict[str, object] = field(default_factory=dict)
    # the package's source directory the summary names
    source_path: str = None


@dataclass
class MergeOutcome:
    """What a merge did; ``problems`` make its exit code 1."""

    merged: List[str] = field(default_factory=list)
    # {package: [the build bases that held the same analysis]}
    duplicates: Dict[str, List[str]] = field(default_factory=dict)
    problems: List[str] = field(default_factory=list)
    notes: List[str] = field(default_factory=list)


class MergeUsageError(ValueError):
    """Build bases that cannot be merged at all."""


def merge_build_bases(sources, target):
    """Merge the package results of the build bases ``sources`` into ``target``.

    :raises MergeUsageError: when the target is one of the sources
    :returns: a :class:`MergeOutcome`
    """
    target = os.path.abspath(target)
    bases = []
    for source in sources:
        source = os.path.abspath(source)
        if _same_directory(source, target):
            raise MergeUsageError(
                f"--from '{display(source)}' is the build base merged into "
                '(--build-base): name the shards other than the target')
        if not any(_same_directory(source, b) for b in bases):
            bases.append(source)
    outcome = MergeOutcome()
    by_package = {}
    for base in bases:
        results, problems = read_build_base(base)
        outcome.problems += problems
        for result in results:
            by_package.setdefault(result.package, []).append(result)
    for package, results in sorted(by_package.items()):
        chosen = _choose(package, results, outcome)
        if chosen is None:
            continue
        try:
            write_result(target, chosen)
        except OSError as e:
            outcome.problems.append(
                f'{display(package)}: cannot write into '
                f"'{display(os.path.join(target, package))}': "
                f'{e.strerror or e}; not merged')
            continue
        outcome.merged.append(package)
        if chosen.source_path and not os.path.isdir(chosen.source_path):
            outcome.notes.append(
                f'{display(package)}: its summary was made from the sources '
                f"at '{display(chosen.source_path)}', not a directory here: "
                "'--since' and the report find a package's files only at "
                'the path it was analysed at (check out at the same path in '
                'every job)')
    return outcome


def _same_directory(a, b):
    try:
        return os.path.samefile(a, b)
    except OSError:
        return os.path.realpath(a) == os.path.realpath(b)


def _choose(package, results, outcome):
    first = results[0]
    for other in results[1:]:
        difference = _difference(first, other)
        if difference:
            outcome.problems.append(
                f"{display(package)}: the build bases '{display(first.build_base)}' "
                f"and '{display(other.build_base)}' hold different analyses "
                f'of it ({difference}); not merged, the target keeps what it '
                'had. Analyse a package with the same sources, version and '
                'settings in every shard that analyses it')
            return None
    if len(results) > 1:
        outcome.duplicates[package] = [r.build_base for r in results]
    return first


def _difference(a, b):
    """What differs between two analyses of a package, in words, or ''."""
    said = []
    for name in RESULT_FILES:
        if (name in a.comparable) != (name in b.comparable):
            holder = a if name in a.comparable else b
            said.append(f"only '{display(holder.build_base)}' has {name}")
        elif name in a.comparable and a.comparable[name] != b.comparable[name]:
            left, right = a.comparable[name], b.comparable[name]
            keys = sorted(k for k in set(left) | set(right)
                          if left.get(k) != right.get(k))
            said.append(f"{name} differs in {', '.join(keys)}")
    return '; '.join(said)


def read_build_base(build_base):
    """The package results a build base holds, and the problems met.

    :returns: ``([PackageResult], [message])``
    """
    try:
        names = sorted(os.listdir(build_base))
    except FileNotFoundError:
        return [], [f"--from '{display(build_base)}' does not exist; "
                    'nothing merged from it']
    except OSError as e:
        return [], [f"--from '{display(build_base)}' cannot be read: "
                    f'{e.strerror or e}; nothing merged from it']
    results = []
    problems = []
    for name in names:
        rsia = os.path.join(build_base, name, store.RSIA_DIRNAME)
        present = [f for f in RESULT_FILES
                   if os.path.isfile(os.path.join(rsia, f))]
        if not present:
            continue
        if build_paths.name_problem(name):
            continue
        result, problem = _read_result(build_base, name, present)
        if problem:
            problems.append(problem)
        else:
            results.append(result)
    if not results and not problems:
        problems.append(
            f"--from '{display(build_base)}' holds no analysis results "
            '(no <package>/rsia/summary.json): was it the build base of '
            "'colcon rsia analyze' or of a build with '--event-handlers "
            "rsia+'?")
    return results, problems


def _read_result(build_base, name, present):
    """Read one package's files; return (PackageResult, None) or (None, why)."""
    rsia = os.path.join(build_base, name, store.RSIA_DIRNAME)
    result = PackageResult(package=name, build_base=build_base)
    if store.SUMMARY_FILENAME not in present and \
            store.FAILURE_FILENAME not in present:
        return None, (
            f"{display(name)}: '{display(rsia)}' has "
            f'{wrapper_store.WRAPPERS_FILENAME} but no {store.SUMMARY_FILENAME}: '
            'an incomplete copy of the build base? not merged')
    for filename in present:
        path = os.path.join(rsia, filename)
        try:
            text = read_bytes(path, limit=store.SUMMARY_SIZE_FACTOR *
                              max_file_bytes()).decode('utf-8')
            data = json.loads(text)
        except RecursionError:
            return None, _corrupt(name, path, 'nested too deeply')
        except (OSError, ValueError) as e:
            return None, _corrupt(name, path, e)
        if not isinstance(data, dict):
            return None, _corrupt(name, path, 'not a JSON object')
        problem = _CHECKS[filename](data)
        if problem:
            return None, f"{display(name)}: '{display(path)}' {problem}"
        result.texts[filename] = text
        result.comparable[filename] = {
            k: v for k, v in data.items()
            if filename != store.SUMMARY_FILENAME or
            k not in VOLATILE_SUMMARY_FIELDS}
        if filename == store.SUMMARY_FILENAME:
            result.source_path = data.get('path')
    return result, None


def _corrupt(name, path, why):
    return (f"{display(name)}: '{display(path)}' is corrupt ({why}); not "
            "merged: re-run the shard's analysis of the package")


def _schema_problem(found, wanted):
    return (f'has the schema {display(str(found))!r}, this version of '
            f'colcon-rsia reads {wanted!r}; not merged (the file is left as '
            'it is): analyse the package again with this version, or merge '
            'with the version that wrote it')


def _check_summary(data):
    if data.get('schema') != SUMMARY_SCHEMA:
        return _schema_problem(data.get('schema'), SUMMARY_SCHEMA)
    try:
        PackageSummary.from_dict(data)
    except (ValueError, RecursionError) as e:
        return f"cannot be used ({e}); not merged: re-run the shard's analysis"
    return None


def _check_failure(data):
    if not isinstance(data.get('error'), str):
        return "is corrupt (no 'error' text); not merged"
    return None


def _check_wrappers(data):
    if data.get('schema') != wrapper_store.WRAPPERS_SCHEMA:
        return _schema_problem(data.get('schema'), wrapper_store.WRAPPERS_SCHEMA)
    try:
        if not isinstance(data['path'], str):
            raise TypeError('path is not a string')
        for wrapper in data['wrappers']:
            WrapperSummary(**wrapper)
    except (KeyError, TypeError, AttributeError) as e:
        return f"is corrupt ({e!r}); not merged: re-run the shard's analysis"
    return None


_CHECKS = {
    store.SUMMARY_FILENAME: _check_summary,
    store.FAILURE_FILENAME: _check_failure,
    wrapper_store.WRAPPERS_FILENAME: _check_wrappers,
}


def write_result(target, result):
    """Make the target's files of the package those of ``result``.

    Each file is written atomically; a file the result lacks is removed
    from the target (a failure that is no longer one, wrappers the package
    no longer has), as the analysis itself does.
    """
    rsia = os.path.join(target, result.package, store.RSIA_DIRNAME)
    for filename in RESULT_FILES:
        path = os.path.join(rsia, filename)
        if filename in result.texts:
            write_text_atomically(path, result.texts[filename])
        else:
            try:
                os.unlink(path)
            except FileNotFoundError:
                pass
