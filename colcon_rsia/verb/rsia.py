# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

import argparse
import os
import sys

from colcon_core.command import add_subparsers
from colcon_core.plugin_system import satisfies_version
from colcon_core.verb import VerbExtensionPoint
from colcon_rsia.subverb import get_subverb_extensions

# argparse exits 2 on a usage error; for rsia 2 means that --fail-on
# matched, so a usage error exits 1 like every other error
USAGE_ERROR_EXIT_CODE = 1


def _argparse_parser(parser):
    """The plain argparse parser under colcon's parser decorators.

    Decorators (colcon-argcomplete's, colcon-defaults') forward attribute
    reads and writes to the parser they wrap, and some define their own
    ``parse_known_args`` that calls the wrapped one: patching through them
    would make such a method call itself.
    """
    while not isinstance(parser, argparse.ArgumentParser):
        parser = parser.__dict__['_decoree']
    return parser


def exit_1_on_usage_errors(parser):
    """Make a usage error of `parser` (or of an argument left over) exit 1.

    Arguments nobody takes would reach colcon's own parser, which exits 2;
    they are reported here instead. Only argparse's own methods are called,
    so this holds whatever decorates the parser.
    """
    parser = _argparse_parser(parser)

    def error(message):
        parser.print_usage(sys.stderr)
        parser.exit(USAGE_ERROR_EXIT_CODE, f'{parser.prog}: error: {message}\n')

    def parse_all_args(args=None, namespace=None):
        namespace, extras = argparse.ArgumentParser.parse_known_args(
            parser, args, namespace)
        if extras:
            error(f"unrecognized arguments: {' '.join(extras)}")
        return namespace, extras

    parser.error = error
    parser.parse_known_args = parse_all_args


def _stop_quietly_on_closed_pipe(main):
    """Wrap a subverb's main: a reader that stops reading ends it quietly.

    ``colcon rsia graph | head`` closes the pipe while the output is being
    written; that is what the user asked for, not an error.
    """
    def main_until_the_pipe_closes(*, context):
        try:
            return main(context=context)
        except BrokenPipeError:
            # Python would complain again when flushing stdout at exit
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
            return 0
    return main_until_the_pipe_closes


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
                    subverb_parser.set_defaults(main=_stop_quietly_on_closed_pipe(
                        subverb_parser.get_default('main')))

    def main(self, *, context):  # noqa: D102
        # error: no subverb provided
        if context.args.subverb_name is None:
            print(self._subparser.format_usage())
            return 'Error: No subverb provided'
