# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What the analysis of a package understood, against its source text.

The call sites that create publishers and subscriptions are found in the
package's own files by text (:mod:`colcon_rsia.package.call_sites`), independently
of the front ends; each is then looked up among the facts: recorded for a
node, recorded only in a unit's facts (code no node runs, such as a plugin),
or not recorded at all (a blind spot). With the parse errors left in each
translation unit, this is the ``coverage`` section of a summary.
"""

import collections

from colcon_rsia.package.call_sites import CXX_HEADER_EXTENSIONS
from colcon_rsia.package.call_sites import CXX_SOURCE_EXTENSIONS
from colcon_rsia.package.call_sites import PUBLISHER
from colcon_rsia.package.call_sites import scan_package
from colcon_rsia.package.call_sites import SUBSCRIBER
from colcon_rsia.summary.coverage import CallSiteCoverage
from colcon_rsia.summary.coverage import Coverage
from colcon_rsia.summary.kinds import ORIGIN_AST
from colcon_rsia.summary.kinds import ORIGIN_TOKENS
from colcon_rsia.summary.kinds import UNKNOWN_NAMESPACE

# a call written over several lines is recorded at the line of its callee
# name or of its object: both lie within this many lines of each other
LINE_SLACK = 2

RECORDED_IN_NODE = 'node'
RECORDED_IN_UNIT = 'unit'
NOT_RECORDED = 'none'
# in a header no translation unit includes: code the build never compiles
# (not counted against the analysis)
IN_UNREAD_FILE = 'unread'


def fact_lines(holders, origins=None):
    """{(file, role): [lines]} of the endpoints of nodes or of units.

    Both hold ``publishers`` and ``subscribers`` facts located at
    ``file:line``. `origins`, when given, collects {(file, role, line):
    {origin}} of the facts.
    """
    lines = collections.defaultdict(list)
    for holder in holders:
        for role, facts in ((PUBLISHER, holder.publishers),
                            (SUBSCRIBER, holder.subscribers)):
            for fact in facts:
                for location in _places(fact):
                    file, _, line = location.rpartition(':')
                    if line.isdigit():
                        lines[(file, role)].append(int(line))
                        if origins is not None:
                            origins[(file, role, int(line))].add(fact.origin)
    return lines


def _places(fact):
    """A fact's location, and the library's place that made it (made_in)."""
    made_in = getattr(fact, 'made_in', None)
    return [fact.location] + ([made_in] if made_in else [])


def _origin(site, origins):
    """'tokens' when only facts read from tokens are near a site."""
    near = set().union(*(
        origins.get((site.file, site.role, line), set())
        for line in range(site.line - LINE_SLACK, site.line + LINE_SLACK + 1)))
    return ORIGIN_TOKENS if near == {ORIGIN_TOKENS} \
        else ORIGIN_AST


def match_sites(sites, lines):
    """The call sites matched one to one with a recorded line.

    A site takes the fact on its own line first. The others are paired
    nearest first, across all sites, within :data:`LINE_SLACK` lines. A
    fact is recorded where its call expression starts, at or before the
    line of the callee's name (``pub_ = Class<M, P>::`` on one line,
    ``create_publisher(`` on the next): a fact before the site is nearer
    than one after it at the same distance.
    """
    free = {key: collections.Counter(value) for key, value in lines.items()}
    matched = set()
    for site in sites:
        candidates = free.get((site.file, site.role))
        if candidates and candidates[site.line] > 0:
            candidates[site.line] -= 1
            matched.add(site)
    pairs = []
    for number, site in enumerate(sites):
        if site in matched:
            continue
        for line in free.get((site.file, site.role)) or {}:
            distance = abs(line - site.line)
            if distance <= LINE_SLACK:
                after = line > site.line
                pairs.append((distance + after * 0.5, number, line))
    for _, number, line in sorted(pairs):
        site = sites[number]
        candidates = free[(site.file, site.role)]
        if site not in matched and candidates[line] > 0:
            candidates[line] -= 1
            matched.add(site)
    return matched


def call_site_coverage(sites, *, nodes, units, not_built=frozenset()):
    """[CallSiteCoverage] of these sites against recorded facts.

    :param nodes: the package's nodes (Node)
    :param units: the facts of the units parsed (TuFacts); a site in
      a file none of them read is in code the build never compiles
    :param not_built: files of programs no target builds (an example's
      ``main``): code the build never compiles either
    """
    origins = collections.defaultdict(set)
    in_nodes = match_sites(sites, fact_lines(nodes, origins))
    rest = [s for s in sites if s not in in_nodes]
    in_units = match_sites(rest, fact_lines(units, origins))
    rest = [s for s in rest if s not in in_units]
    through_node, through_unit = _through_package_functions(
        rest, nodes, units)
    in_nodes |= through_node
    in_units |= through_unit
    read = {file for unit in units for file in unit.files}
    result = []
    for site in sites:
        recorded = IN_UNREAD_FILE if site.file in not_built else \
            RECORDED_IN_NODE if site in in_nodes else \
            RECORDED_IN_UNIT if site in in_units else \
            IN_UNREAD_FILE if site.file not in read else NOT_RECORDED
        result.append(CallSiteCoverage(
            file=site.file, line=site.line, role=site.role, api=site.api,
            recorded=recorded, origin=_origin(site, origins) if recorded in (
                RECORDED_IN_NODE, RECORDED_IN_UNIT) else None))
    return result


# calls of calls: deeper chains of the package's own functions are not
# followed to an endpoint
MAX_CALL_DEPTH = 3


def _through_package_functions(sites, nodes, units):
    """Sites that call a package function which makes the endpoint.

    ``sub_graph_.subscribe(*this, 1)`` of a helper class defined in another
    file of the package: the subscription is recorded where the helper
    makes it, and the call site is understood through the call edge.
    Returns ({sites whose endpoint is in a node}, {only in a unit}).
    """
    if not sites:
        return set(), set()
    # {function: {(role, location)}} made in its own body
    made = collections.defaultdict(set)
    for unit in units:
        for role, facts in ((PUBLISHER, unit.publishers),
                            (SUBSCRIBER, unit.subscribers)):
            for fact in facts:
                if fact.function:
                    made[fact.function].add((role, fact.location))
    calls = collections.defaultdict(set)
    for unit in units:
        for call in unit.calls:
            if call.kind == 'call':
                calls[call.caller].add(call.callee)

    reached_from = {}

    def reached(function):
        # many call sites call the same helper: its endpoints, found once
        if function not in reached_from:
            found, frontier, seen = set(), {function}, {function}
            for _ in range(MAX_CALL_DEPTH):
                for current in frontier:
                    found |= made.get(current, set())
                frontier = {c for f in frontier
                            for c in calls.get(f, ())} - seen
                seen |= frontier
            reached_from[function] = found
        return reached_from[function]

    in_nodes = {(role, location) for node in nodes
                for role, facts in ((PUBLISHER, node.publishers),
                                    (SUBSCRIBER, node.subscribers))
                for f in facts for location in _places(f)}
    # {(file, role): [(line, endpoints the call makes)]}
    call_lines = collections.defaultdict(list)
    for unit in units:
        for call in unit.calls:
            if call.kind != 'call' or call.callee not in made and \
                    call.callee not in calls:
                continue
            file, _, line = call.location.rpartition(':')
            if not line.isdigit():
                continue
            endpoints = reached(call.callee)
            for role in (PUBLISHER, SUBSCRIBER):
                own = {e for e in endpoints if e[0] == role}
                if own:
                    call_lines[(file, role)].append((int(line), own))
    through_node, through_unit = set(), set()
    for site in sites:
        candidates = [
            endpoints for line, endpoints in call_lines.get(
                (site.file, site.role), ())
            if abs(line - site.line) <= LINE_SLACK]
        if not candidates:
            continue
        if any(e in in_nodes for endpoints in candidates for e in endpoints):
            through_node.add(site)
        else:
            through_unit.add(site)
    return through_node, through_unit


def package_call_sites(path, *, python):
    """The package's call sites in Python files, or in C++ files."""
    cxx = CXX_SOURCE_EXTENSIONS + CXX_HEADER_EXTENSIONS
    return [s for s in scan_package(path)
            if s.file.endswith(cxx) != python]


# --- the workspace report (`colcon rsia coverage`) --------------------------

COVERAGE_SCHEMA = 'colcon-rsia/coverage@1'

# package states in the report
ANALYSED = 'analysed'
FAILED = 'failed'
NOT_ANALYSED = 'not analysed'


def package_report(summary):
    """The coverage of one analysed package, as the JSON contract has it."""
    report = {'package': summary.package, 'status': ANALYSED,
              'has_coverage': summary.coverage is not None}
    coverage = summary.coverage or Coverage()
    report['units'] = len(coverage.units)
    report['units_with_errors'] = sum(
        1 for u in coverage.units if u.package_errors)
    report['units_losing_calls'] = sum(
        1 for u in coverage.units if u.lost_calls)
    report['units_repaired'] = sum(
        1 for u in coverage.units if u.repair_rounds)
    report['call_sites'] = {}
    for role in (PUBLISHER, SUBSCRIBER):
        sites = [c for c in coverage.call_sites
                 if c.role == role and c.recorded != IN_UNREAD_FILE]
        report['call_sites'][role] = {
            'sites': len(sites),
            'in_nodes': sum(1 for c in sites
                            if c.recorded == RECORDED_IN_NODE),
            'in_units_only': sum(1 for c in sites
                                 if c.recorded == RECORDED_IN_UNIT),
            'from_tokens': sum(1 for c in sites
                               if c.origin == ORIGIN_TOKENS)}
    report['missed'] = [
        {'file': c.file, 'line': c.line, 'role': c.role, 'api': c.api}
        for c in coverage.call_sites if c.recorded == NOT_RECORDED]
    report['in_unread_files'] = [
        {'file': c.file, 'line': c.line, 'role': c.role, 'api': c.api}
        for c in coverage.call_sites if c.recorded == IN_UNREAD_FILE]
    report['unresolved_topics'] = [
        {'node': node.id, 'role': role, 'topic': endpoint.topic,
         'location': endpoint.location}
        for node in summary.nodes
        for role, endpoints in ((PUBLISHER, node.publishers),
                                (SUBSCRIBER, node.subscribers))
        for endpoint in endpoints if not endpoint.topic_is_literal or
        (endpoint.namespace or '').startswith(UNKNOWN_NAMESPACE)]
    report['unnamed_nodes'] = sorted(
        node.id for node in summary.nodes if not node.name)
    # which rules of the model mode's recovery repaired what, where
    report['repairs'] = [
        {'file': u.file, 'rule': rule, 'kind': kind, 'name': name}
        for u in coverage.units for rule, kind, name in u.repairs]
    return report


def workspace_report(summaries, failures=None, not_analysed=()):
    """The coverage of a workspace: per package and in total.

    :param summaries: the packages' summaries
    :param failures: {package: why its last analysis failed}
    :param not_analysed: selected packages with neither
    """
    packages = [package_report(s) for s in summaries]
    for package, error in sorted((failures or {}).items()):
        packages = [p for p in packages if p['package'] != package]
        packages.append({'package': package, 'status': FAILED,
                         'error': error})
    packages += [{'package': p, 'status': NOT_ANALYSED}
                 for p in sorted(not_analysed)]
    packages.sort(key=lambda p: p['package'])
    analysed = [p for p in packages if p['status'] == ANALYSED]
    total = {
        'packages': len(packages),
        'failed': sum(1 for p in packages if p['status'] == FAILED),
        'not_analysed': sum(
            1 for p in packages if p['status'] == NOT_ANALYSED),
        'units': sum(p['units'] for p in analysed),
        'units_with_errors': sum(p['units_with_errors'] for p in analysed),
        'units_losing_calls': sum(
            p.get('units_losing_calls', 0) for p in analysed),
        'unresolved_topics': sum(
            len(p['unresolved_topics']) for p in analysed),
        'unnamed_nodes': sum(len(p['unnamed_nodes']) for p in analysed),
        'call_sites': {}}
    for role in (PUBLISHER, SUBSCRIBER):
        total['call_sites'][role] = {
            key: sum(p['call_sites'][role][key] for p in analysed)
            for key in ('sites', 'in_nodes', 'in_units_only', 'from_tokens')}
    total['percent'] = recorded_percent(total)
    total['repairs'] = dict(sorted(collections.Counter(
        r['rule'] for p in analysed for r in p.get('repairs', ())).items()))
    return {'schema': COVERAGE_SCHEMA, 'packages': packages, 'total': total}


def recorded_percent(counts):
    """The share of call sites whose fact belongs to a node, in %.

    A fact recorded only in code no node runs (a plugin nobody hosts, a
    helper no executable links) is not covered: it is in no system graph.
    """
    sites = sum(c['sites'] for c in counts['call_sites'].values())
    recorded = sum(c['in_nodes'] for c in counts['call_sites'].values())
    return round(100.0 * recorded / sites, 1) if sites else 100.0
