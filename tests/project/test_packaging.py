# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""colcon conventions: environment variables, license, Debian metadata."""

import configparser
import os
from pathlib import Path
import subprocess
import sys

from colcon_rsia.frontend import compile_db
import pytest

REPO = Path(__file__).resolve().parents[2]
OUR_VARIABLES = {
    'COLCON_RSIA_ALLOWED_ROOTS', 'COLCON_RSIA_CACHE_DIR',
    'COLCON_RSIA_CACHE_MB', 'COLCON_RSIA_CLANG_RESOURCE_DIR',
    'COLCON_RSIA_CMAKE_WITHOUT_SANDBOX',
    'COLCON_RSIA_CXX_STD', 'COLCON_RSIA_HEADER_MODE',
    'COLCON_RSIA_MAX_FILE_MB', 'COLCON_RSIA_UNIT_TIMEOUT'}


def test_environment_variables_are_listed_by_colcon_help():
    colcon = Path(sys.executable).parent / 'colcon'
    result = subprocess.run(
        [str(colcon), '--help'], capture_output=True, text=True,
        timeout=120, env=dict(os.environ, COLUMNS='200'))
    assert result.returncode == 0, result.stderr
    epilog = result.stdout.split('Environment variables:', 1)[1]
    listed = {line.split()[0] for line in epilog.splitlines()
              if line.startswith('  COLCON_RSIA_')}
    assert listed == OUR_VARIABLES
    assert 'Exception' not in result.stderr


@pytest.fixture
def fresh_resource_dir(monkeypatch):
    monkeypatch.setattr(compile_db, '_resource_dir_cache', [])
    for name in ('COLCON_RSIA_CLANG_RESOURCE_DIR', 'RSIA_CLANG_RESOURCE_DIR'):
        monkeypatch.delenv(name, raising=False)
    return monkeypatch


def _resource_dir(root, name):
    directory = root / name
    (directory / 'include').mkdir(parents=True)
    (directory / 'include' / 'stddef.h').write_text('')
    return str(directory)


def test_clang_resource_dir_from_the_environment(fresh_resource_dir, tmp_path):
    chosen = _resource_dir(tmp_path, 'new')
    fresh_resource_dir.setenv('COLCON_RSIA_CLANG_RESOURCE_DIR', chosen)
    fresh_resource_dir.setenv(
        'RSIA_CLANG_RESOURCE_DIR', _resource_dir(tmp_path, 'old'))
    assert compile_db.find_resource_dir() == chosen


def test_clang_resource_dir_under_its_old_name(fresh_resource_dir, tmp_path):
    chosen = _resource_dir(tmp_path, 'old')
    fresh_resource_dir.setenv('RSIA_CLANG_RESOURCE_DIR', chosen)
    assert compile_db.find_resource_dir() == chosen


def test_license_and_metadata():
    text = (REPO / 'LICENSE').read_text()
    assert text.lstrip().startswith('Apache License')
    assert 'Version 2.0, January 2004' in text
    setup = configparser.ConfigParser()
    setup.read(REPO / 'setup.cfg')
    assert setup['metadata']['license'] == 'Apache-2.0'
    # no address until the project has one of its own
    assert 'url' not in setup['metadata']
    stdeb = configparser.ConfigParser()
    stdeb.read(REPO / 'stdeb.cfg')
    depends = stdeb['colcon-rsia']['Depends3']
    # every runtime requirement has its Debian package
    for debian in ('python3-colcon-core', 'python3-clang',
                   'python3-defusedxml', 'python3-networkx', 'python3-yaml'):
        assert debian in depends
    requirements = setup['options']['install_requires'].split()
    assert {r.split('>=')[0] for r in requirements} == {
        'colcon-core', 'libclang', 'networkx', 'pyyaml', 'defusedxml'}
