# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The documentation stays true: API lists, links, README size."""

from pathlib import Path
import re

from colcon_rsia.frontend import python_api
from colcon_rsia.frontend import ros_api

REPO = Path(__file__).resolve().parents[2]
DOCS = REPO / 'docs'
README = REPO / 'README.md'
# not the project's files: tools' state, build output
SKIPPED = {
    '.git', '.venv', '.pytest_cache', '.hypothesis', '.benchmarks',
    'build', 'install', 'log', '__pycache__'}


def _api_table(name):
    text = (DOCS / 'apis.md').read_text()
    match = re.search(
        rf'<!-- api-table: {name} -->\n(.*?)<!-- /api-table -->', text,
        re.S)
    assert match, f'docs/apis.md has no api-table {name}'
    names = set()
    for row in match.group(1).splitlines()[2:]:
        cells = row.split('|')
        names.update(re.findall(r'`([^`]+)`', cells[2]))
    return names


def test_cpp_apis_in_the_docs_are_those_of_the_table():
    assert _api_table('cpp') == set(ros_api.CALLS) | set(ros_api.DECLARED)


def test_python_apis_in_the_docs_are_those_of_the_table():
    assert _api_table('python') == set(python_api.CALLS)


def test_api_table_parser_reads_every_name_of_a_row():
    # the parser above must see each name of a cell, not only the first
    text = (DOCS / 'apis.md').read_text()
    row = next(line for line in text.splitlines()
               if line.startswith('| rate objects |'))
    assert len(re.findall(r'`([^`]+)`', row)) > 1


def test_readme_is_short_and_keeps_the_quick_start():
    text = README.read_text()
    assert len(text.splitlines()) <= 150
    assert 'bash .ci/example' in text
    assert 'bash .ci/run' in text


def _markdown_files():
    return [README] + sorted(DOCS.rglob('*.md'))


def _anchor(heading):
    # GitHub's anchors: lower case, punctuation dropped, spaces -> '-'
    text = heading.strip().lower()
    text = re.sub(r'[^\w\- ]', '', text)
    return text.replace(' ', '-')


def _anchors(path):
    text = re.sub(r'```.*?```', '', path.read_text(), flags=re.S)
    return {_anchor(m.group(1))
            for m in re.finditer(r'^#+ (.+)$', text, re.M)}


def test_links_between_documents_resolve():
    broken = []
    for path in _markdown_files():
        text = re.sub(r'```.*?```', '', path.read_text(), flags=re.S)
        for target in re.findall(r'\]\(([^)\s]+)\)', text):
            if re.match(r'[a-z]+:', target):
                continue  # a web address
            file, _, anchor = target.partition('#')
            resolved = (path.parent / file) if file else path
            if not resolved.exists():
                broken.append(f'{path.name}: {target}')
            elif anchor and resolved.suffix == '.md' and \
                    anchor not in _anchors(resolved):
                broken.append(f'{path.name}: {target} (no such heading)')
    assert broken == []


def test_anchor_of_a_heading_with_code():
    assert _anchor('Launch files: `--launch`') == 'launch-files---launch'


def _project_files():
    for path in sorted(REPO.rglob('*')):
        parts = path.relative_to(REPO).parts
        if any(p in SKIPPED or p.endswith('.egg-info') for p in parts) or \
                not path.is_file():
            continue
        if path.suffix in ('.png', '.svg', '.pyc'):
            continue
        yield path


def test_no_file_cites_paths_outside_the_repository():
    # the project's notes and references live outside it; readers of the
    # repository cannot follow such paths
    outside = re.compile(r'shared/reference|\.\./shared|/work/|DESIGN\.md')
    citing = []
    for path in _project_files():
        try:
            text = path.read_text()
        except (UnicodeDecodeError, OSError):
            continue
        if path == Path(__file__).resolve():
            continue
        if outside.search(text):
            citing.append(str(path.relative_to(REPO)))
    assert citing == []
