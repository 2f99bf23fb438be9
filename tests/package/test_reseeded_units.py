# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A unit parsed once more, seeded with what its package learnt since.

Which facts are kept (units.py); when a unit is parsed again, and that it
then parses clean, is in tests/frontend/test_shared_repairs.py.
"""

from colcon_rsia.frontend.compile_db import CompileEntry
from colcon_rsia.frontend.facts import TuFacts
from colcon_rsia.package import units
from colcon_rsia.package.cache import read_cached_facts
from colcon_rsia.package.cache import unit_cache_file
from colcon_rsia.package.cache import write_cached_facts

DIGEST = 'wrappers:when-it-pays'


def _parse_again(tmp_path, monkeypatch, second):
    """(the unit's facts kept, the undos called, its cached facts)."""
    source = tmp_path / 'node.cpp'
    source.write_text('int main() { return 0; }\n')
    entry = CompileEntry(file=str(source), directory=str(tmp_path),
                         arguments=[])
    cache = str(tmp_path / 'cache')
    first = TuFacts(source='node.cpp', package_errors=2, errors=2)
    write_cached_facts(unit_cache_file(cache, entry), entry, [entry.file],
                       first, DIGEST)
    undone = []

    def reseed(entry, facts, errors, *, workspace):
        return lambda: undone.append(entry.file)

    def parse(function, items, *, context, **_):
        # (as the workers' parse does: the second parse caches its facts)
        assert context['reseeded']
        write_cached_facts(unit_cache_file(cache, entry), entry,
                           [entry.file], second, DIGEST)
        return [(True, (second, []))], []
    monkeypatch.setattr(units, 'parse', parse)
    found = [(first, [])]
    units._parse_reseeded(
        [0], [entry], found, reseed=reseed, context=dict(
            cache=cache, shared=None, shared_repairs=None,
            precompiled_dir=None, wrappers_digest=DIGEST),
        jobs=1, timeout=60)
    return found[0][0], undone, read_cached_facts(
        unit_cache_file(cache, entry), entry, DIGEST)


def test_a_better_second_parse_is_kept(tmp_path, monkeypatch):
    second = TuFacts(source='node.cpp', repair_rounds=1)
    kept, undone, cached = _parse_again(tmp_path, monkeypatch, second)
    assert kept is second
    assert undone == []
    assert (cached.package_errors, cached.repair_rounds) == (0, 1)


def test_a_second_parse_no_better_leaves_the_first(tmp_path, monkeypatch):
    second = TuFacts(
        source='node.cpp', package_errors=3, errors=3, repair_rounds=1)
    kept, undone, cached = _parse_again(tmp_path, monkeypatch, second)
    # the first facts, their repairs put back, and the parse counted
    assert (kept.package_errors, kept.repair_rounds) == (2, 1)
    assert len(undone) == 1
    # the next run reads what this one kept
    assert (cached.package_errors, cached.repair_rounds) == (2, 1)
