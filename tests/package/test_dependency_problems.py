# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Which dependencies' analysis a package's analysis finds missing.

A C++ package reads the wrappers of its dependencies' libraries from their
analysis in the same build base (tests/package/test_shards.py runs the whole
story through colcon); these are the cases decided from the build base's
files alone.
"""

from colcon_rsia import __version__
from colcon_rsia.package.dependencies import dependency_problems
from colcon_rsia.summary import store
from colcon_rsia.summary.package_summary import PackageSummary


def _analyzed(build, name, source):
    store.write_summary(str(build / name), PackageSummary(
        package=name, path=str(source), tool_version=__version__))


def test_each_dependency_without_an_analysis_of_its_sources(tmp_path):
    build = tmp_path / 'build'
    src = tmp_path / 'src'
    _analyzed(build, 'here', src / 'here')
    # the output of a package of the same name from another source tree
    _analyzed(build, 'moved', tmp_path / 'old' / 'moved')
    store.write_failure(str(build / 'failed'), 'failed',
                        'no compile_commands.json')
    (build / 'broken' / 'rsia').mkdir(parents=True)
    (build / 'broken' / 'rsia' / 'summary.json').write_text('{"nodes": [')
    dependencies = [(name, src / name) for name in (
        'here', 'moved', 'failed', 'never', 'broken')]
    problems = dependency_problems(str(build / 'app'), dependencies)
    assert [p.split(':')[0] for p in problems] == [
        'the dependency broken has no analysis of its sources in this '
        'build base',
        'the analysis of the dependency failed failed (no compile_commands.json)',
        'the dependency moved has no analysis of its sources in this '
        'build base',
        'the dependency never has no analysis of its sources in this '
        'build base']
    assert all(p.endswith((
        'analyse this package again', 'give no facts here'))
        for p in problems)


def test_a_summary_analyzed_again_is_read_again(tmp_path):
    build = tmp_path / 'build'
    dependency = [('lib', tmp_path / 'src' / 'lib')]
    _analyzed(build, 'lib', tmp_path / 'elsewhere' / 'lib')
    assert len(dependency_problems(str(build / 'app'), dependency)) == 1
    _analyzed(build, 'lib', tmp_path / 'src' / 'lib')
    assert dependency_problems(str(build / 'app'), dependency) == []
