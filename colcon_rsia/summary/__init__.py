# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The package summary: the contract between the two phases.

Build time (``package/``) writes it, query time (``system/``,
``report/``) reads it: the data classes serialised into ``summary.json``
(``package_summary``, ``nodes``, ``coverage``, the vocabularies in
``kinds``), reading and writing the files (``store``), and the wrapper
summaries a package offers the packages analysed after it
(``wrapper_store``). It imports nothing of either phase.
"""
