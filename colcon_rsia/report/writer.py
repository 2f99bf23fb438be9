# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Write the report's files (see :mod:`colcon_rsia.report`)."""

import os

from colcon_rsia.render import json_text
from colcon_rsia.render.graph import graph_to_dot
from colcon_rsia.report import build_report
from colcon_rsia.report.drawing import draw_system
from colcon_rsia.report.html import graph_svg
from colcon_rsia.report.html import render_html
from colcon_rsia.report.markdown import render_summary
from colcon_rsia.safe_files import write_text_atomically
from colcon_rsia.system.impact import PAPER
from colcon_rsia.system.rates import predict_rates


def write_report(system, output, *, changed=None, reasons=None, since=None,
                 dot_executable=None, model_name=PAPER):
    """Write the report files into the directory `output`.

    :param changed: instance ids of the changed nodes, or None
    :param reasons: {instance id: [why it counts as changed]}
    :param since: the ``--since`` revision, when the changes came from git
    :param dot_executable: Graphviz ``dot``; default: ``dot`` on PATH
    :param model_name: the rate dependency model of the impact sets
    :returns: (names of the files written, notes on what could not be
      done as usual)
    """
    data = build_report(system, changed=changed, reasons=reasons, since=since,
                        model_name=model_name)
    drawing, layout_note = draw_system(system, dot_executable=dot_executable)
    written = []
    notes = []
    # every file is rendered before any is written: a failure leaves the
    # directory as it was, never a half-written or empty index.html
    rendered = {}

    def write(name, text):
        rendered[name] = text
        written.append(name)

    write('index.html', render_html(data, drawing))
    impact = data.impact or {}
    write('graph.dot', graph_to_dot(
        system, changed=set(data.changed or ()),
        rate_impact=set(impact.get('rate_impact', ())),
        traditional=set(impact.get('traditional_impact', ())),
        rates=predict_rates(system)))
    write('graph.json', json_text(data.graph))
    stale = []
    if data.impact is not None:
        write('impact.json', json_text(data.impact))
    else:
        stale.append('impact.json')
    write('summary.md', render_summary(data))
    write('graph.svg', graph_svg(data, drawing, standalone=True) + '\n')
    if layout_note:
        notes.append(layout_note)
    os.makedirs(output, exist_ok=True)
    for name, text in rendered.items():
        write_text_atomically(os.path.join(output, name), text)
    # files of an earlier report that this one does not have
    for name in stale:
        try:
            os.unlink(os.path.join(output, name))
        except FileNotFoundError:
            pass
    return sorted(written), notes
