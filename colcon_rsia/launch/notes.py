# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""How the launch readers write their notes: short quotes, each note once.

The lowest launch module (it imports nothing), so that every other one,
down to :mod:`colcon_rsia.launch.safe_eval`, can use it without a cycle.
"""


def shorten(text, limit=60):
    """The first ``limit`` characters of a text quoted in a message.

    Launch files can hold values of any length; a note quotes enough to
    find the place, not the whole value.
    """
    text = str(text)
    return text if len(text) <= limit else text[:limit] + '…'


def unique(notes):
    """The notes in their order, each once (several paths note the same)."""
    seen = set()
    return [n for n in notes if not (n in seen or seen.add(n))]
