# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Build time: one package's sources -> facts -> labels -> summary.json.

Runs once per package, after colcon built it (the event handler) or on
demand (``colcon rsia analyze``). Reads the package's code through the
front ends (:mod:`colcon_rsia.frontend`), finds its nodes (CMake, setup
files, plugin XML), assembles and labels each node's facts and writes one
``PackageSummary`` (:mod:`colcon_rsia.summary`) into the package's build
directory. Nothing here knows about other packages or launch files.
"""
