# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""How the report scales: write time, page size and load time.

For generated systems of 200 and 1,000 nodes (tests/synthetic_system.py,
summaries only, no compile): the seconds `write_report` takes (Graphviz
layout included), the size of index.html, and the seconds headless Chromium
takes from navigation to the page's script having drawn the graph.

RESULT n200_write_s=<s> n200_page_mb=<MB> n200_load_s=<s> n1000_write_s=...
"""

from pathlib import Path
import shutil
import sys
import tempfile
import time

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / 'tests'))

from colcon_rsia.report.writer import write_report  # noqa: E402
from colcon_rsia.system.load import load_system  # noqa: E402
from headless import Browser  # noqa: E402
from headless import find_chromium  # noqa: E402
from synthetic_system import changed_node  # noqa: E402
from synthetic_system import synthetic_summaries  # noqa: E402

SIZES = (200, 1000)


def measure(count, directory, chromium):
    system = load_system(synthetic_summaries(count))
    changed = changed_node(count)
    output = directory / f'report-{count}'
    started = time.monotonic()
    _, notes = write_report(system, str(output), changed=[changed],
                            reasons={changed: ['benchmark']})
    write_s = time.monotonic() - started
    if notes:
        print(f'notes at {count} nodes: {notes}')
    page = output / 'index.html'
    with Browser(chromium, str(directory / f'profile-{count}')) as browser:
        started = time.monotonic()
        browser.open(page.as_uri())
        assert browser.evaluate(
            "document.body.getAttribute('data-rendered')") == 'true'
        load_s = time.monotonic() - started
        problems = browser.problems()
    if problems:
        raise SystemExit(f'the page of {count} nodes logged: {problems}')
    return write_s, page.stat().st_size / 1e6, load_s


def main():
    chromium = find_chromium()
    if chromium is None:
        raise SystemExit('chromium is needed (.ci/install installs it)')
    if shutil.which('dot') is None:
        print('note: Graphviz dot is not on PATH; measuring the built-in '
              'layout')
    directory = Path(tempfile.mkdtemp(prefix='rsia-report-scale-'))
    try:
        fields = []
        for count in SIZES:
            write_s, page_mb, load_s = measure(count, directory, chromium)
            print(f'{count} nodes: report written in {write_s:.2f} s, '
                  f'index.html {page_mb:.2f} MB, loaded in {load_s:.2f} s')
            fields += [f'n{count}_write_s={write_s:.2f}',
                       f'n{count}_page_mb={page_mb:.2f}',
                       f'n{count}_load_s={load_s:.2f}']
        print('RESULT ' + ' '.join(fields))
    finally:
        shutil.rmtree(directory, ignore_errors=True)


if __name__ == '__main__':
    main()
