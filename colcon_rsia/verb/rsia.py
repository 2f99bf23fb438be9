# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

from colcon_core.command import add_subparsers
from colcon_core.plugin_system import satisfies_version
from colcon_core.verb import VerbExtensionPoint
from colcon_rsia.subverb import get_subverb_extensions


class RsiaVerb(VerbExtensionPoint):
    """Rate impact analysis: which nodes may change rate after a change."""

    def __init__(self):  # noqa: D107
        super().__init__()
        satisfies_version(VerbExtensionPoint.EXTENSION_POINT_VERSION, '^1.0')

    def add_arguments(self, *, parser):  # noqa: D102
        self._subparser = parser
        # get subverb extensions and let them add their arguments
        subverb_extensions = get_subverb_extensions()
        add_subparsers(
            parser, 'colcon rsia', subverb_extensions,
            attribute='subverb_name')

    def main(self, *, context):  # noqa: D102
        # error: no subverb provided
        if context.args.subverb_name is None:
            print(self._subparser.format_usage())
            return 'Error: No subverb provided'
