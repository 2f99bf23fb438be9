# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""``--since REF``: the changed nodes from the files git says changed.

A changed file maps to every node instance whose ``files`` (the package's
files its code is read from, :attr:`colcon_rsia.summary.nodes.Node.files`) hold it;
a changed launch or parameter file of the ``--launch`` files maps to every
instance (the launch file may have changed any of them). Committed and
working-tree changes count (``git diff --name-only REF``); untracked files
do not.
"""

import os
import subprocess

GIT_TIMEOUT_S = 60


class ChangeError(RuntimeError):
    """The changed files cannot be found (one sentence, no traceback)."""


def _real(path):
    return os.path.normcase(os.path.realpath(path))


def _git(args, cwd):
    try:
        return subprocess.run(
            ['git'] + list(args), cwd=cwd, capture_output=True,
            timeout=GIT_TIMEOUT_S)
    except FileNotFoundError:
        raise ChangeError('--since needs git, which is not on PATH')
    except subprocess.TimeoutExpired:
        raise ChangeError(
            f"'git {' '.join(args)}' did not finish within "
            f'{GIT_TIMEOUT_S} s in {cwd}')


def repository_of(path):
    """The top-level directory of the git repository holding a path, or None.

    A path that does not exist is looked up from its nearest existing parent.
    """
    directory = os.path.abspath(path)
    while not os.path.isdir(directory):
        parent = os.path.dirname(directory)
        if parent == directory:
            return None
        directory = parent
    result = _git(['rev-parse', '--show-toplevel'], directory)
    if result.returncode != 0:
        return None
    return result.stdout.decode('utf-8', 'surrogateescape').strip() or None


def changed_files(ref, paths):
    """The files changed since `ref` in the repositories holding `paths`.

    :param ref: a commit-ish (``origin/main``, ``HEAD~1``, a sha, …)
    :param paths: directories or files whose repositories are diffed
    :returns: the absolute real paths of the changed files, sorted
    :raises ChangeError: when no path is in a git repository, or no
      repository knows `ref`
    """
    repositories = sorted({r for r in map(repository_of, paths) if r})
    if not repositories:
        raise ChangeError(
            f'--since {ref}: the analysed packages are not in a git '
            'repository')
    if ref.startswith('-'):
        raise ChangeError(f'--since {ref}: not a git revision')
    files = set()
    known = 0
    unknown = []
    for repository in repositories:
        check = _git(
            ['rev-parse', '--verify', '--quiet', f'{ref}^{{commit}}'],
            repository)
        if check.returncode != 0:
            unknown.append(repository)
            continue
        known += 1
        # -z: names unquoted; --no-renames: a renamed file is old and new
        diff = _git(['diff', '--name-only', '--no-renames', '-z', ref, '--'],
                    repository)
        if diff.returncode != 0:
            message = diff.stderr.decode('utf-8', 'replace').strip()
            raise ChangeError(
                f'--since {ref}: git diff failed in {repository}: '
                f"{message.splitlines()[-1] if message else 'no message'}")
        for name in diff.stdout.decode('utf-8', 'surrogateescape').split(
                '\0'):
            if name:
                files.add(_real(os.path.join(repository, name)))
    if not known:
        where = unknown[0] if len(unknown) == 1 else \
            f'any of {", ".join(unknown)}'
        raise ChangeError(
            f'--since {ref}: unknown revision in the git repository '
            f'{where}')
    return sorted(files)


def package_sources(system):
    """{package: source path} of the analysed packages of a system graph."""
    return dict(getattr(system, 'package_sources', None) or {})


def map_changed_files(system, files, *, package_paths=None,
                      launch_files=None):
    """The instances the changed files belong to, with the reasons.

    :param files: absolute paths of changed files
    :param package_paths: {package: source path} the nodes' ``files`` are
      relative to; default: what :func:`colcon_rsia.system.load.load_system`
      recorded on the system
    :param launch_files: the launch and parameter files the system was
      read from; default: what ``load_system`` recorded
    :returns: {instance id: [reason, …]}, ids and reasons sorted
    """
    if package_paths is None:
        package_paths = package_sources(system)
    if launch_files is None:
        launch_files = getattr(system, 'launch_files', None) or []
    changed = {_real(f): f for f in files}
    reasons = {}
    for instance in sorted(system.instances.values(), key=lambda i: i.id):
        node = instance.node
        base = package_paths.get(instance.package)
        if node is None or not base:
            continue
        for name in sorted(set(node.files) | set(node.sources)):
            if _real(os.path.join(base, name)) in changed:
                reasons.setdefault(instance.id, []).append(
                    f'{os.path.normpath(name)} changed')
    changed_launch = sorted(
        launch for launch in launch_files if _real(launch) in changed)
    for launch in changed_launch:
        for instance_id in sorted(system.instances):
            reasons.setdefault(instance_id, []).append(
                f'launch file {_display(launch)} changed')
    return {k: sorted(set(v)) for k, v in sorted(reasons.items())}


def _display(path):
    """A path as short as it is clear: relative to the cwd when inside it."""
    relative = os.path.relpath(path)
    return path if relative.startswith('..') else relative


def changed_since(system, ref, *, package_paths=None, launch_files=None):
    """The instances changed since `ref`, with the reasons.

    :returns: {instance id: [reason, …]}
    :raises ChangeError: see :func:`changed_files`
    """
    if package_paths is None:
        package_paths = package_sources(system)
    if launch_files is None:
        launch_files = getattr(system, 'launch_files', None) or []
    paths = list(package_paths.values()) + list(launch_files)
    if not paths:
        raise ChangeError(f'--since {ref}: no package has been analysed yet')
    files = changed_files(ref, paths)
    return map_changed_files(
        system, files, package_paths=package_paths,
        launch_files=launch_files)


def describe_reasons(system, reasons):
    """One line per changed instance: ``pkg/exe: src/foo.cpp changed``."""
    lines = []
    for instance_id, why in reasons.items():
        instance = system.instances.get(instance_id)
        name = instance_id
        if instance is not None:
            node_id = f'{instance.package}/{instance.executable}'
            if node_id != instance_id:
                name = f'{instance_id} ({node_id})'
        lines.append(f"{name}: {'; '.join(why)}")
    return lines
