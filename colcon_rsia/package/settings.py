# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A setting's number read from its environment variable.

Imports nothing of the package: the modules whose settings
``environment.environment_problems`` checks up front use it too.
"""

import math
import os


def positive_number(name, *, default, unit, what):
    """The number a variable holds, its default when it is unset.

    :param unit: the unit the message names (``seconds``)
    :param what: what the number is, for the message
    :raises ValueError: one sentence, when the value is not a positive,
      finite number
    """
    text = os.environ.get(name, '').strip()
    if not text:
        return float(default)
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value) or value <= 0:
        raise ValueError(
            f'{name}={text!r} is not a positive number of {unit} ({what}; '
            f'unset, it is {default})')
    return value
