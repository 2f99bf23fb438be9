# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The command-line options the rsia subverbs share."""

from colcon_core.argument_default import wrap_default_value
from colcon_core.argument_type import get_cwd_path_resolver
from colcon_core.package_selection import add_arguments \
    as add_packages_arguments
from colcon_rsia.render import FORMATS
from colcon_rsia.system.impact import MODELS
from colcon_rsia.system.impact import PAPER


def add_workspace_arguments(parser):
    """Add --build-base and colcon's package selection arguments."""
    # the summaries live in the build directory of each package; declared
    # as colcon build declares it (a relative path is taken from the
    # current directory, and a defaults.yaml value is told from a given one)
    parser.add_argument(
        '--build-base',
        default=wrap_default_value('build'),
        type=get_cwd_path_resolver(),
        help='The base path for all build directories, where the analysis '
             'summaries are (default: build)')
    add_packages_arguments(parser)


def add_system_arguments(parser):
    """Add the workspace arguments and --launch."""
    add_workspace_arguments(parser)
    parser.add_argument(
        '--launch', nargs='+', metavar='ARG',
        help='The deployed system: a launch file (FILE or PKG FILE) and its '
             'name:=value arguments; without it every analysed node runs '
             'once in the root namespace')


def add_model_argument(parser):
    """Add ``--model paper|trigger``."""
    parser.add_argument(
        '--model', choices=MODELS, default=PAPER,
        help='How a rate change crosses a node: paper (to every dependent '
             "publisher, the paper's Algorithm 2) or trigger (only to "
             'the dependent publishers the incoming topic triggers) '
             '(default: paper)')


def add_since_argument(group):
    """Add ``--since REF`` (to the group holding ``--changed``)."""
    group.add_argument(
        '--since', metavar='REF',
        help='The changed nodes are those whose files (or whose launch '
             'files) changed since the git revision REF: committed and '
             'working-tree changes, as `git diff --name-only REF`')


def add_format_argument(parser, formats=FORMATS):
    """Add ``--format`` with the formats the subverb's result renders to.

    :param formats: the choices (``colcon_rsia.render``), the default first
    """
    parser.add_argument(
        '--format', choices=formats, default=formats[0],
        help=f'Output format (default: {formats[0]})')
