# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The per-unit fact cache: ``build/<pkg>/rsia/cache/<digest>.json``.

A translation unit is parsed again only when its source, a header it
includes, its compiler flags or the code that makes facts changed; a cache
that is missing, unreadable or of another version is never trusted.
"""

import hashlib
import json
import os

from colcon_rsia import __version__
from colcon_rsia import safe_files
from colcon_rsia.frontend.facts import FACTS_SCHEMA
from colcon_rsia.frontend.facts import TuFacts


def unit_cache_file(cache_dir, entry):
    """The cache file of the unit of a compile-database entry."""
    digest = hashlib.sha1(os.fsencode(entry.file)).hexdigest()[:16]
    return os.path.join(cache_dir, digest + '.json')


def _file_stamp(path):
    try:
        st = os.stat(path)
    except OSError:
        return None
    return [st.st_mtime_ns, st.st_size]


_FRONTEND_DIGEST = []


def _frontend_digest():
    """A digest of the code that makes facts: new code, new facts."""
    if not _FRONTEND_DIGEST:
        digest = hashlib.sha1()
        # the colcon_rsia directory: this module is in colcon_rsia/package
        here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
        files = [os.path.join(here, relative) for relative in (
            'frontend/facts.py', 'frontend/fact_builder.py',
            'frontend/recorder.py', 'summary/kinds.py',
            'summary/wrapper_store.py', 'frontend/ros_api.py')]
        # the C++ front end's modules (the model mode's too), and the
        # model headers
        for root, dirs, names in sorted(os.walk(
                os.path.join(here, 'frontend', 'cpp'))):
            dirs.sort()
            files += [os.path.join(root, n) for n in sorted(names)
                      if n.endswith('.py')]
        for root, dirs, names in sorted(os.walk(
                os.path.join(here, 'frontend', 'model_headers'))):
            dirs.sort()
            files += [os.path.join(root, n) for n in sorted(names)]
        for file in files:
            with open(file, 'rb') as h:
                digest.update(h.read())
        _FRONTEND_DIGEST.append(digest.hexdigest())
    return _FRONTEND_DIGEST[0]


def _cache_key(entry, wrappers):
    return {'tool': __version__, 'schema': FACTS_SCHEMA,
            'frontend': _frontend_digest(),
            'arguments': entry.arguments, 'directory': entry.directory,
            'wrappers': wrappers}


def read_cached_facts(cache_file, entry, wrappers=None):
    """The cached facts of a unit, or None when any input changed.

    :param wrappers: the digest of the other packages' wrapper summaries
      the unit was walked with (wrapper_store.wrappers_digest)
    """
    try:
        with open(cache_file, encoding='utf-8') as h:
            data = json.load(h)
        if data['key'] != _cache_key(entry, wrappers):
            return None
        for path, stamp in data['inputs'].items():
            if _file_stamp(path) != stamp:
                return None
        return TuFacts.from_dict(data['facts'])
    except (OSError, ValueError, KeyError, TypeError):
        return None  # no cache, or one we cannot trust: parse again


def cached_inputs(cache_file):
    """The files a unit's cached facts were made from, or None."""
    try:
        with open(cache_file, encoding='utf-8') as h:
            return list(json.load(h)['inputs'])
    except (OSError, ValueError, KeyError, TypeError):
        return None


def write_cached_facts(cache_file, entry, inputs, facts, wrappers=None):
    """Cache a unit's facts with the stamps of the files it read."""
    data = {
        'key': _cache_key(entry, wrappers),
        'inputs': {p: _file_stamp(p) for p in inputs},
        'facts': facts.to_dict()}
    try:
        safe_files.write_json_atomically(cache_file, data)
    except OSError:
        pass  # a cache that cannot be written only costs time
