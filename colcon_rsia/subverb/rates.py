# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

import math

from colcon_core.logging import colcon_logger
from colcon_core.plugin_system import satisfies_version
from colcon_rsia.subverb import RsiaSubverbExtensionPoint
from colcon_rsia.subverb.arguments import add_format_argument
from colcon_rsia.subverb.arguments import add_model_argument
from colcon_rsia.subverb.arguments import add_system_arguments
from colcon_rsia.system.workspace import load_system_from_args
from colcon_rsia.system.workspace import select_changed

logger = colcon_logger.getChild(__name__)


class RatesRsiaSubverb(RsiaSubverbExtensionPoint):
    """Print the predicted publishing rate of every topic (and what if)."""

    def __init__(self):  # noqa: D107
        super().__init__()
        satisfies_version(
            RsiaSubverbExtensionPoint.EXTENSION_POINT_VERSION, '^1.0')

    def add_arguments(self, *, parser):  # noqa: D102
        add_system_arguments(parser)
        parser.add_argument(
            '--set-rate', action='append', metavar='TOPIC=HZ', default=[],
            help='What if TOPIC published at HZ: print the topics whose '
                 'rate changes and those an edge keeps (repeatable)')
        parser.add_argument(
            '--changed', nargs='+', metavar='PKG/EXE',
            help='What if these nodes changed: their topics may publish '
                 'at any rate')
        add_model_argument(parser)
        add_format_argument(parser)

    def main(self, *, context):  # noqa: D102
        from colcon_rsia.render.rates import render_rates
        from colcon_rsia.system.rates import rates_to_json
        args = context.args
        set_rates, error = parse_set_rates(args.set_rate)
        if error:
            return error
        system, error = load_system_from_args(args, logger)
        if error:
            return error
        unknown = sorted(set(set_rates) - set(system.topics()))
        if unknown:
            return f"--set-rate: no topic {', '.join(unknown)} in the " \
                'system (see colcon rsia rates)'
        changed, _, error = select_changed(system, args)
        if error:
            return error
        result = rates_to_json(
            system, set_rates=set_rates, changed=changed or (),
            model_name=args.model)
        print(render_rates(result, args.format), end='')
        return 0


def parse_set_rates(values):
    """{topic: Hz} from ``TOPIC=HZ`` strings, or an error message."""
    rates = {}
    for value in values:
        topic, _, hz = value.rpartition('=')
        try:
            number = float(hz)
        except ValueError:
            number = None
        # nan, inf and 1e400 (inf) are no rate, and no JSON number
        if not topic.startswith('/') or number is None or \
                not math.isfinite(number) or number < 0:
            return None, f'--set-rate {value!r}: expected /TOPIC=HZ ' \
                '(a global topic name and a finite rate >= 0)'
        rates[topic] = number
    return rates, None
