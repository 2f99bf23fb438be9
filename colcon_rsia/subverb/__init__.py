# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

import os

from colcon_core.package_selection import add_arguments \
    as add_packages_arguments
from colcon_core.package_selection import get_packages
from colcon_core.plugin_system import instantiate_extensions
from colcon_core.plugin_system import order_extensions_by_name
from colcon_rsia.store import find_summaries
from colcon_rsia.store import read_summary
from colcon_rsia.store import SummaryError


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


def load_selected_summaries(args, logger):
    """Read the summaries of the selected packages.

    Packages that were not analysed are skipped; an unusable summary is
    reported in one line and skipped, never hiding the others.

    :returns: the summaries and the names of the selected packages
    """
    selected = selected_package_names(args)
    found = find_summaries(os.path.abspath(args.build_base))
    summaries = []
    for name, path in sorted(found.items()):
        if selected is not None and name not in selected:
            continue
        try:
            summaries.append(read_summary(path))
        except SummaryError as e:
            logger.warning(str(e))
    return summaries


def selected_package_names(args):
    """Names of the selected packages, or None to take every summary."""
    try:
        decorators = get_packages(args)
    except RuntimeError:
        return None
    names = {d.descriptor.name for d in decorators if d.selected}
    if not names and not decorators:
        # no package found under the base paths: use every summary
        return None
    return names
