# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Every problem the last analysis of each package met, one per line.

A summary keeps its problems as the lines the analysis printed
(``diagnostics``): most start with the file they concern, relative to the
package (``src/a.cpp: ...``), and a parse error names the place clang
reported (``src/a.cpp: parse error: /ws/src/pkg/include/a.h:12: ...``).
This module splits those lines into file, line and reason for the
``problems`` command; a line naming no file keeps ``file`` and ``line``
``None``.
"""

import os
import re

from colcon_rsia.safe_files import printable_lines

PROBLEMS_SCHEMA = 'colcon-rsia/problems@1'

ANALYSED = 'analysed'
FAILED = 'failed'
NOT_ANALYSED = 'not_analysed'

# `path[:line[:column]]: reason`; a path has no blank (a sentence that
# starts a diagnostic, "executable 'x': ...", is no path)
_LOCATED = re.compile(
    r'(?P<file>[^\s:]+)(?::(?P<line>\d+))?(?::\d+)?: (?P<reason>.*)', re.S)
PARSE_ERROR = 'parse error: '


def split_problem(text, package_path=None):
    """``{'file', 'line', 'unit', 'reason'}`` of one diagnostic line.

    :param package_path: the package's directory: a place clang reported
      inside it is given relative to it
    """
    problem = {'file': None, 'line': None, 'unit': None, 'reason': text}
    match = _LOCATED.fullmatch(text)
    if match is None:
        return problem
    problem.update(file=match.group('file'), reason=match.group('reason'))
    if match.group('line'):
        problem['line'] = int(match.group('line'))
    if problem['reason'].startswith(PARSE_ERROR):
        # the unit that was parsed, and the place of the error within it
        inner = _LOCATED.fullmatch(problem['reason'][len(PARSE_ERROR):])
        if inner is not None:
            problem['unit'] = problem['file']
            problem['file'] = _relative(inner.group('file'), package_path)
            problem['line'] = int(inner.group('line')) \
                if inner.group('line') else None
            problem['reason'] = PARSE_ERROR + inner.group('reason')
    return problem


def _relative(path, package_path):
    if package_path and os.path.isabs(path):
        relative = os.path.relpath(path, package_path)
        if not relative.startswith('..'):
            return relative
    return path


def problems_report(summaries, failures=None, not_analysed=()):
    """The ``colcon-rsia/problems@1`` document of the selected packages.

    :param summaries: the analysed packages' summaries
    :param failures: ``{package: message}`` of those whose analysis failed
    :param not_analysed: names of those never analysed
    """
    packages = []
    for summary in summaries:
        packages.append({
            'package': summary.package, 'status': ANALYSED,
            'problems': [split_problem(d, summary.path)
                         for d in summary.diagnostics]})
    for name, message in (failures or {}).items():
        packages.append({
            'package': name, 'status': FAILED,
            'problems': [{'file': None, 'line': None, 'unit': None,
                          'reason': message}]})
    for name in not_analysed:
        packages.append({'package': name, 'status': NOT_ANALYSED,
                         'problems': []})
    packages.sort(key=lambda p: p['package'])
    return {
        'schema': PROBLEMS_SCHEMA, 'packages': packages,
        'total': sum(len(p['problems']) for p in packages)}


def problem_to_text(problem):
    """``file:line: reason (in unit)``, the parts known."""
    where = problem['file'] or ''
    if problem['line'] is not None:
        where += f":{problem['line']}"
    unit = f" (in {problem['unit']})" if problem['unit'] and \
        problem['unit'] != problem['file'] else ''
    return f"{where + ': ' if where else ''}{problem['reason']}{unit}"


def problems_to_text(report):
    """One line per problem, under a line per package that has any."""
    lines = []
    for package in report['packages']:
        name = package['package']
        if package['status'] == NOT_ANALYSED:
            lines.append(f"{name}: not analysed (run 'colcon rsia analyze' "
                         'or build with --event-handlers rsia+)')
            continue
        problems = package['problems']
        if package['status'] == FAILED:
            lines.append(f'{name}: analysis failed: '
                         f"{problems[0]['reason']}")
            continue
        if not problems:
            continue
        lines.append(f'{name}: {len(problems)} '
                     f"problem{'s' if len(problems) != 1 else ''}")
        lines += ['  ' + problem_to_text(p) for p in problems]
    analysed = sum(1 for p in report['packages']
                   if p['status'] != NOT_ANALYSED)
    total = report['total']
    lines.append(f"{total} problem{'s' if total != 1 else ''} in "
                 f"{analysed} analysed package{'s' if analysed != 1 else ''}")
    return printable_lines(lines)
