# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

import argparse
import sys

from colcon_core.command import add_subparsers
from colcon_core.plugin_system import satisfies_version
from colcon_core.verb import VerbExtensionPoint
from colcon_rsia.subverb import get_subverb_extensions

# argparse exits 2 on a usage error; for rsia 2 means that --fail-on
# matched, so a usage error exits 1 like every other error
USAGE_ERROR_EXIT_CODE = 1


def exit_1_on_usage_errors(parser):
    """Make a usage error of `parser` (or of an argument left over) exit 1.

    Arguments nobody takes would reach colcon's own parser, which exits 2;
    they are reported here instead.
    """
    def error(message):
        parser.print_usage(sys.stderr)
        parser.exit(USAGE_ERROR_EXIT_CODE, f'{parser.prog}: error: {message}\n')

    parse_known_args = parser.parse_known_args

    def parse_all_args(args=None, namespace=None):
        namespace, extras = parse_known_args(args, namespace)
        if extras:
            error(f"unrecognized arguments: {' '.join(extras)}")
        return namespace, extras

    parser.error = error
    parser.parse_known_args = parse_all_args


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
        exit_1_on_usage_errors(parser)
        for action in parser._actions:
            if isinstance(action, argparse._SubParsersAction):
                for subverb_parser in action.choices.values():
                    exit_1_on_usage_errors(subverb_parser)

    def main(self, *, context):  # noqa: D102
        # error: no subverb provided
        if context.args.subverb_name is None:
            print(self._subparser.format_usage())
            return 'Error: No subverb provided'
