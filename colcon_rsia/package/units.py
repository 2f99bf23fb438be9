# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The facts of a package's units: from the cache, or parsed.

The units whose inputs have not changed since their facts were cached are
read; the others are parsed in worker processes (workers.py). In the model
mode, a unit parsed before its package learnt what it lacks may be parsed
once more (recovery.reseed).
"""

import os

from colcon_rsia import safe_files
from colcon_rsia.package.cache import cached_inputs
from colcon_rsia.package.cache import read_cached_facts
from colcon_rsia.package.cache import unit_cache_file
from colcon_rsia.package.cache import write_cached_facts
from colcon_rsia.package.problems import PARSE_ERROR
from colcon_rsia.package.problems import split_problem
from colcon_rsia.package.workers import check_stop
from colcon_rsia.package.workers import Interrupted
from colcon_rsia.package.workers import parse
from colcon_rsia.summary import wrapper_store


def parse_units(entries, *, unit_facts, package_path, resource_dir, cache,
                jobs, timeout, wrappers=(), precompiled_dir=None,
                repair=None, shared=None, shared_repairs=None,
                plan_headers=None, reseed=None):
    """Facts of a package's TUs; return (facts by file, messages).

    The units whose facts are cached are read here; the others are parsed
    in worker processes: one that crashes libclang or takes longer than
    ``timeout`` loses only itself.

    :param unit_facts: the function that parses one unit (entry and the
      keyword arguments below; analysis._unit_facts)
    :param precompiled_dir: where the model mode's precompiled standard
      headers are kept (None: parse without them)
    :param wrappers: the WrapperSummary of the workspace's other
      packages, for the calls of functions whose body is out of sight
    :param float timeout: the seconds one unit may take
    :param repair: when the model mode repairs a unit (for unit_facts)
    :param shared: the shared_cache.SharedCache looked in after ``cache``
      (and given to unit_facts, which stores the facts it makes), or None
    :param shared_repairs: a function making the model mode's repairs the
      workspace's units share (for unit_facts), called only when a unit is
      parsed; or None
    :param plan_headers: exact mode: the function that plans which system
      headers the units to parse share, precompiled in ``precompiled_dir``
      (shared_headers.plan); None for the model mode
    :param reseed: the model mode: recovery.reseed, of the package's path
      (the units it seeds again are parsed once more); or None
    :raises Interrupted: when :func:`request_stop` was called
    """
    hidden = _unsafe_includes(entries, package_path)
    # (the cached facts of a unit depend on its repairs too)
    digest = f'{wrapper_store.wrappers_digest(wrappers)}:{repair}'
    if shared is not None:
        # (libclang sees the hidden files empty: other facts)
        shared = shared.with_hidden(hidden)
    found = [_checked_or_cached(entry, package_path, cache, digest, shared)
             for entry in entries]
    todo = [i for i, result in enumerate(found) if result is None]
    if shared_repairs is not None:
        shared_repairs = shared_repairs() if todo else None
    package_headers = None
    if plan_headers is not None:
        # (a file libclang must see empty could be among those headers)
        package_headers = {} if hidden else \
            plan_headers([entries[i] for i in todo])
    context = dict(
        unit_facts=unit_facts, package_path=package_path,
        resource_dir=resource_dir, cache=cache, hidden=hidden,
        wrappers=wrappers, wrappers_digest=digest,
        precompiled_dir=precompiled_dir, repair=repair, shared=shared,
        shared_repairs=shared_repairs, package_headers=package_headers)
    results, diagnostics = parse(
        _guarded, [entries[i] for i in todo], context=context,
        jobs=jobs, timeout=timeout, cleanup_dirs=[cache, precompiled_dir])
    for i, (parsed, result) in zip(todo, results):
        found[i] = result if parsed else (None, [
            f'{_relative(entries[i], package_path)}: not analysed: {result}'])
    if reseed is not None and todo:
        diagnostics += _parse_reseeded(
            [i for i in todo if found[i][0] is not None], entries, found,
            reseed=reseed, context=context, jobs=jobs, timeout=timeout)
    if shared is not None and todo:
        shared.evict()  # what the workers added may pass the size limit
    units = {}
    for entry, (facts, messages) in zip(entries, found):
        if facts is not None:
            units[entry.file] = facts
        diagnostics.extend(messages)
    return units, diagnostics


def _guarded(entry, *, unit_facts, **context):
    """Run the unit's parse; raise nothing but Interrupted."""
    try:
        check_stop()
        return unit_facts(entry, **context)
    except Interrupted:
        raise
    except Exception as e:  # noqa: B902
        # a bug of ours in one unit loses that unit, not the package
        relative = os.path.relpath(entry.file, context['package_path'])
        return None, [f'{relative}: not analysed (internal error: '
                      f'{type(e).__name__}: {e}); please report it']


def _relative(entry, package_path):
    return safe_files.display(os.path.relpath(entry.file, package_path))


def _unsafe_includes(entries, package_path):
    """Files an include could make libclang open that it must not."""
    search_dirs = sorted({d for e in entries for d in safe_files.include_dirs(
        e.arguments, e.directory)})
    return safe_files.unsafe_inputs(
        [e.file for e in entries], search_dirs=search_dirs,
        roots=[package_path] + search_dirs,
        # colcon_rsia itself (its model headers): this module is in
        # colcon_rsia/package
        skip=[os.path.dirname(os.path.dirname(os.path.abspath(__file__)))])


def _checked_or_cached(entry, package_path, cache, wrappers_digest,
                       shared=None):
    """(facts, messages) of a TU known without parsing it, or None.

    Its facts from the cache when nothing it reads changed (the package's
    cache, then the shared one); nothing when it cannot be read.
    """
    relative = _relative(entry, package_path)
    try:
        safe_files.check_file(entry.file, roots=[package_path])
        safe_files.read_head(entry.file, 1)
    except safe_files.UnsafeFileError as e:
        return None, [f'{relative}: {e}']
    except FileNotFoundError:
        pass  # said below
    except OSError as e:
        return None, [f'{relative}: cannot be read ({e.strerror or e})']
    if cache is not None:
        cached = read_cached_facts(
            unit_cache_file(cache, entry), entry, wrappers_digest)
        if cached is not None:
            return cached, list(cached.diagnostics)
        found = shared.lookup(entry, wrappers_digest) \
            if shared is not None else None
        if found is not None:
            cached, inputs = found
            # the next run finds it in the package's cache, without
            # hashing the files again
            write_cached_facts(unit_cache_file(cache, entry), entry, inputs,
                               cached, wrappers_digest)
            return cached, list(cached.diagnostics)
    if not os.path.isfile(entry.file):
        return None, [f'{relative}: source file missing (stale compile '
                      'database?); skipped']
    return None


def _parse_reseeded(parsed, entries, found, *, reseed, context, jobs,
                    timeout):
    """Parse once more the units that start from more now (reseed).

    The better facts are kept, those of the first parse when the second
    is no better (its repairs and cache entry put back too), and either
    way the unit counts one more parse, as a repair round.

    :param parsed: the indices of `entries` parsed, whose `found` has facts
    :returns: messages about the package
    """
    cache, shared = context['cache'], context['shared']
    again = []
    for i in parsed:
        undo = reseed(entries[i], found[i][0], _parse_errors(found[i][0]),
                      workspace=context['shared_repairs'])
        if undo is not None:
            again.append((i, undo, cache and cached_inputs(
                unit_cache_file(cache, entries[i]))))
    if not again:
        return []
    results, diagnostics = parse(
        _guarded, [entries[i] for i, _, _ in again],
        context=dict(context, reseeded=True), jobs=jobs, timeout=timeout,
        cleanup_dirs=[cache, context['precompiled_dir']])
    for (i, undo, inputs), (ok, result) in zip(again, results):
        old = found[i][0]
        if ok and result[0] is not None and \
                _score(result[0]) < _score(old):
            found[i] = result
            continue
        undo()
        old.repair_rounds += 1
        if inputs:
            # (the second parse cached its facts: the kept ones again, made
            # from the same files, the unit's source first)
            write_cached_facts(unit_cache_file(cache, entries[i]),
                               entries[i], inputs, old,
                               context['wrappers_digest'])
            if shared is not None:
                shared.store(entries[i], context['wrappers_digest'],
                             inputs[1:], old)
    return diagnostics


def _parse_errors(facts):
    """[(file, line, message)] of the errors a unit's parse left."""
    errors = []
    for text in facts.diagnostics:
        problem = split_problem(text)
        if problem['unit'] is not None and problem['line'] is not None:
            errors.append((problem['file'], problem['line'],
                           problem['reason'][len(PARSE_ERROR):]))
    return errors


def _score(facts):
    """Which facts of a unit are kept: the lowest wins."""
    return facts.lost_calls, facts.package_errors
