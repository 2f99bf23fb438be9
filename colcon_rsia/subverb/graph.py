# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

from colcon_core.logging import colcon_logger
from colcon_core.plugin_system import satisfies_version
from colcon_rsia.render.graph import FORMATS
from colcon_rsia.render.graph import render_graph
from colcon_rsia.subverb import RsiaSubverbExtensionPoint
from colcon_rsia.subverb.arguments import add_format_argument
from colcon_rsia.subverb.arguments import add_system_arguments
from colcon_rsia.system.workspace import load_system_from_args

logger = colcon_logger.getChild(__name__)


class GraphRsiaSubverb(RsiaSubverbExtensionPoint):
    """Print the rate dependency graph of the analysed packages."""

    def __init__(self):  # noqa: D107
        super().__init__()
        satisfies_version(
            RsiaSubverbExtensionPoint.EXTENSION_POINT_VERSION, '^1.0')

    def add_arguments(self, *, parser):  # noqa: D102
        add_system_arguments(parser)
        add_format_argument(parser, FORMATS)

    def main(self, *, context):  # noqa: D102
        args = context.args
        system, error = load_system_from_args(args, logger)
        if error:
            return error
        print(render_graph(system, args.format), end='')
        return 0
