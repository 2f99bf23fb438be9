# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The output of the query commands, from the results ``system`` computes.

One module per kind of result (``graph``, ``impact``, ``rates``,
``check``, ``coverage``), each with one function per output format and a
``render_<kind>(result, fmt)`` that picks it. A renderer returns the whole
text, ending in a line break; the subverb prints it. Nothing here computes
an answer: a renderer reads only the result it is given.
"""

import json

TEXT = 'text'
JSON = 'json'
DOT = 'dot'
# what every result can be written as; the graph adds DOT
FORMATS = (TEXT, JSON)


def json_text(document):
    """A result document as JSON: indented, keys sorted, a final newline."""
    return json.dumps(document, indent=2, sort_keys=True) + '\n'


def hz_text(hz, missing):
    """``12.5 Hz``; `missing` when there is no rate."""
    return f'{hz:g} Hz' if hz is not None else missing
