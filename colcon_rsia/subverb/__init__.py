# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

import os
import sys

from colcon_core.package_selection import add_arguments \
    as add_packages_arguments
from colcon_core.package_selection import get_packages
from colcon_core.plugin_system import instantiate_extensions
from colcon_core.plugin_system import order_extensions_by_name
from colcon_rsia.package.store import find_summaries
from colcon_rsia.package.store import read_summary
from colcon_rsia.package.store import SummaryError


class RsiaSubverbExtensionPoint:
    """
    The interface for rsia subverb extensions.

    An rsia subverb extension provides a subverb to the `rsia` verb of the
    command line tool.

    For each instance the attribute `SUBVERB_NAME` is being set to the
    basename of the entry point registering the extension.
    """

    """The version of the rsia subverb extension interface."""
    EXTENSION_POINT_VERSION = '1.0'

    def add_arguments(self, *, parser):
        """
        Add command line arguments specific to the subverb.

        The method is intended to be overridden in a subclass.

        :param parser: The argument parser
        """
        pass

    def main(self, *, context):
        """
        Execute the subverb extension logic.

        This method must be overridden in a subclass.

        :param context: The context providing the parsed command line
          arguments
        :returns: The return code
        """
        raise NotImplementedError()


def get_subverb_extensions():
    """
    Get the available subverb extensions.

    The extensions are ordered by their entry point name.

    :rtype: OrderedDict
    """
    extensions = instantiate_extensions(__name__)
    for name, extension in extensions.items():
        extension.SUBVERB_NAME = name
    return order_extensions_by_name(extensions)


def add_workspace_arguments(parser):
    """Add --build-base and colcon's package selection arguments."""
    # the summaries live in the build directory of each package
    parser.add_argument(
        '--build-base',
        default='build',
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


def load_workspace(args, logger):
    """Read the summaries of the selected packages.

    Packages that were not analysed are skipped; an unusable summary is
    reported in one line and skipped, never hiding the others.

    :returns: the summaries and {package name: source path} of the
      packages found under the base paths
    """
    try:
        decorators = get_packages(args)
    except RuntimeError as e:
        logger.warning(str(e))
        decorators = []
    package_paths = {
        d.descriptor.name: str(d.descriptor.path) for d in decorators}
    selected = {d.descriptor.name for d in decorators if d.selected}
    found = find_summaries(os.path.abspath(args.build_base))
    summaries = []
    for name, path in sorted(found.items()):
        # with no package found under the base paths, take every summary
        if decorators and name not in selected:
            continue
        try:
            summaries.append(read_summary(path))
        except SummaryError as e:
            logger.warning(str(e))
    return summaries, package_paths


def load_system_from_args(args, logger):
    """The system graph the arguments describe, or an error message."""
    from colcon_rsia.system.load import LaunchArgumentError
    from colcon_rsia.system.load import load_system
    launch = getattr(args, 'launch', None)
    expected_errors = (LaunchArgumentError,)
    if launch:
        from colcon_rsia.launch import LaunchError
        expected_errors += (LaunchError,)
    summaries, package_paths = load_workspace(args, logger)
    try:
        system = load_system(
            summaries, launch=launch, package_paths=package_paths)
    except expected_errors as e:
        return None, str(e)
    for note in system.notes:
        print(f'note: {note}', file=sys.stderr)
    return system, None
