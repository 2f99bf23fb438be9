# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

from setuptools import setup

setup()
