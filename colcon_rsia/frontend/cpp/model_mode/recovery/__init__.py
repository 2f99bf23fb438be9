# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Recovery: a unit the model mode could not parse cleanly, completed.

The model headers cover the ROS API and the stand-ins the includes nothing
provides; real code still names what neither declares (a library the model
lacks, a base class of it, its macros). An error of the parse can hide a
call the analysis looks for, so a unit whose own files show endpoint calls
without a fact is repaired: clang's diagnostics are matched against a
table of rules (:data:`.rules.RULES`, one row per class of diagnostic,
each with worked examples), whose answers are permissive declarations
(:mod:`.render`) or edits of the code in memory (:mod:`.edits`,
:mod:`.applied`), and the unit is parsed again (:func:`.loop.parse_unit`).
A unit parsed before its package's other units learnt what its errors
show missing is seeded with that and parsed once more (:func:`.reseed`).

No rule names a library: what a name becomes follows from how the code
uses it (:mod:`.naming`: ``ns::`` a namespace, ``(`` a function, ``<`` a
template) and from what is declared already (:mod:`.declared`). A unit's
repairs are data, with the rule that made each (:mod:`.store`), and the
package's summary counts them per rule (``colcon rsia coverage
--repairs``).
"""

from colcon_rsia.frontend.cpp.model_mode.recovery.loop import \
    MAX_REPAIR_ROUNDS
from colcon_rsia.frontend.cpp.model_mode.recovery.loop import parse_unit
from colcon_rsia.frontend.cpp.model_mode.recovery.loop import ParsedUnit
from colcon_rsia.frontend.cpp.model_mode.recovery.loop import \
    workspace_repairs
from colcon_rsia.frontend.cpp.model_mode.recovery.reseed import reseed
from colcon_rsia.frontend.cpp.model_mode.recovery.store import \
    ensure_repair_header
from colcon_rsia.frontend.cpp.model_mode.recovery.store import repair_header

__all__ = [
    'MAX_REPAIR_ROUNDS', 'ParsedUnit', 'ensure_repair_header', 'parse_unit',
    'repair_header', 'reseed', 'workspace_repairs',
]
