# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Query time: the packages' summaries + launch files -> system graph -> impact.

Reads the ``summary.json`` files the build-time phase
(:mod:`colcon_rsia.package`) wrote, places the nodes the launch files
(:mod:`colcon_rsia.launch`) start, connects them by resolved topic names
into one graph and answers impact, rate and report queries on it.
Nothing here reads source code.
"""
