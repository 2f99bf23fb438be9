# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

from pathlib import Path

from flake8.api.legacy import get_style_guide
import pytest


@pytest.mark.flake8
@pytest.mark.linter
def test_flake8():
    root = Path(__file__).resolve().parents[2]
    style_guide = get_style_guide(show_source=True)
    report = style_guide.check_files([
        str(root / 'colcon_rsia'), str(root / 'tests'), str(root / 'bench'),
        str(root / 'setup.py')])
    assert report.total_errors == 0, \
        f'flake8 reported {report.total_errors} errors'
