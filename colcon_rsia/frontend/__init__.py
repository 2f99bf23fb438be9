# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Front ends: source code to function summaries (syntax, not ROS semantics)."""
