# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What the analysis understood of a package: the summary's coverage."""

from dataclasses import dataclass
from dataclasses import field
from typing import List
from typing import Optional


@dataclass
class UnitCoverage:
    """How one translation unit parsed."""

    file: str
    errors: int = 0            # parse errors left, in all
    package_errors: int = 0    # of which in the package's own files
    repair_rounds: int = 0     # parses after the first (model mode)
    # publisher/subscription/publish/timer calls the unit's text shows that
    # the parse lost (an error the repairs left that costs a fact; errors
    # that cost none are left unrepaired when repairing does not pay)
    lost_calls: int = 0
    # [rule id, kind, name or place] of the unit's repairs (model mode)
    repairs: List[List[str]] = field(default_factory=list)


@dataclass
class CallSiteCoverage:
    """One publisher/subscription call site the source text shows."""

    file: str
    line: int
    role: str       # 'publisher' | 'subscriber'
    api: str
    recorded: str   # 'node' | 'unit' (facts no node runs) | 'none'
    # of a recorded site: 'ast', or 'tokens' (read where the parse lost it)
    origin: Optional[str] = None


@dataclass
class Coverage:
    """What the analysis understood of a package (see coverage.py)."""

    units: List[UnitCoverage] = field(default_factory=list)
    call_sites: List[CallSiteCoverage] = field(default_factory=list)

    @classmethod
    def from_dict(cls, data):  # noqa: D102
        return cls(
            units=[UnitCoverage(**u) for u in data.get('units', [])],
            call_sites=[CallSiteCoverage(**c)
                        for c in data.get('call_sites', [])])
