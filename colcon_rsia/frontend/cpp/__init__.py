# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The C++ front end: a libclang walk from a translation unit to its facts.

:func:`parse` a unit (:mod:`.parse`), then :func:`extract_facts` walks the
package's own code in it (:mod:`.walker`, with the handlers of the API
roles in :mod:`.roles`, :mod:`.clocks` and :mod:`.wrappers`). The model
header mode, which parses without the real ROS headers, is
:mod:`.model_mode`.
"""

from colcon_rsia.frontend.cpp.cursors import normalize_msg_type
from colcon_rsia.frontend.cpp.parse import error_diagnostics
from colcon_rsia.frontend.cpp.parse import MAX_DIAGNOSTICS_PER_TU
from colcon_rsia.frontend.cpp.parse import parse
from colcon_rsia.frontend.cpp.parse import parse_diagnostics
from colcon_rsia.frontend.cpp.walker import extract_facts

__all__ = [
    'error_diagnostics', 'extract_facts', 'MAX_DIAGNOSTICS_PER_TU',
    'normalize_msg_type', 'parse', 'parse_diagnostics',
]
