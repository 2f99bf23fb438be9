# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Name resolution and the two impact analyses on small graphs."""

from colcon_rsia.summary.kinds import DEPENDENT
from colcon_rsia.summary.kinds import INDEPENDENT
from colcon_rsia.summary.nodes import LabelledPublisher
from colcon_rsia.summary.nodes import Node
from colcon_rsia.summary.nodes import NodeSubscriber
from colcon_rsia.summary.package_summary import PackageSummary
from colcon_rsia.system.graph import build_graph
from colcon_rsia.system.impact import expand_changed
from colcon_rsia.system.impact import impact_all
from colcon_rsia.system.impact import rate_impact
from colcon_rsia.system.impact import traditional_impact
from colcon_rsia.system.impact import UnknownNodeError
from colcon_rsia.system.names import join
from colcon_rsia.system.names import resolve
import pytest


def test_resolve_global_relative_private_and_handle_namespaces():
    assert resolve('/scan', node_name='n') == '/scan'
    assert resolve('scan', node_name='n') == '/scan'
    assert resolve('scan', node_name='n', namespace='/robot') == '/robot/scan'
    assert resolve('~scan', node_name='n', namespace='/robot') == \
        '/robot/n/scan'
    assert resolve('~/scan', node_name='n') == '/n/scan'
    assert resolve('scan', node_name='n', handle_namespace='~') == '/n/scan'
    assert resolve('scan', node_name='n', namespace='/r',
                   handle_namespace='front') == '/r/front/scan'
    assert resolve('scan', node_name='n', namespace='/r',
                   handle_namespace='/abs') == '/abs/scan'
    assert resolve('a//b/', node_name='n') == '/a/b'
    assert resolve(None, node_name='n') is None


def _publisher(topic, label):
    return LabelledPublisher(
        topic=topic, topic_is_literal=True, msg_type='m', api='a',
        handle='h', namespace='', location='f:1', label=label,
        pattern='timer' if label == INDEPENDENT else 'none',
        rate_hz=None)


def _subscriber(topic):
    return NodeSubscriber(
        topic=topic, topic_is_literal=True, msg_type='m', api='a',
        callback='cb', namespace='', location='f:2')


def _system(spec):
    """spec: {name: ([(topic, label)], [subscribed topics])}."""
    nodes = [
        Node(id=f'p/{name}', package='p', executable=name,
             kind='executable',
             publishers=[_publisher(t, lbl) for t, lbl in pubs],
             subscribers=[_subscriber(t) for t in subs])
        for name, (pubs, subs) in spec.items()]
    summary = PackageSummary(
        package='p', path='/p', tool_version='0', nodes=nodes)
    return build_graph([summary])


I, D = INDEPENDENT, DEPENDENT
# a -> b (dependent) -> c (independent) -> d; c -> e dependent; d <-> a cycle
SYSTEM = {
    'a': ([('x', I)], ['w']),
    'b': ([('y', D)], ['x']),
    'c': ([('z', I), ('v', D)], ['y']),
    'd': ([('w', D)], ['z']),
    'e': ([], ['v']),
}


def test_rate_impact_stops_at_independent_edges_of_unchanged_nodes():
    system = _system(SYSTEM)
    # a's own independent edge is relabelled dependent: b; b -> c; c's
    # independent z is not crossed, its dependent v is: e
    assert rate_impact(system, ['p/a']) == ['p/b', 'p/c', 'p/e']
    assert traditional_impact(system, ['p/a']) == \
        ['p/a', 'p/b', 'p/c', 'p/d', 'p/e']


def test_changed_node_listed_only_when_reached_again():
    system = _system(SYSTEM)
    # d -> w (dependent) -> a; a changed? no: a's x is independent, stop
    assert rate_impact(system, ['p/d']) == ['p/a']
    # both changed: d reaches a, a (relabelled) reaches b, c; c's z stays
    # independent so d is not reached again
    assert rate_impact(system, ['p/a', 'p/d']) == ['p/a', 'p/b', 'p/c', 'p/e']
    # c changed with d: c -> z (relabelled) -> d, d -> a: the cycle closes
    # only through a's independent edge, so c is not listed
    assert rate_impact(system, ['p/c', 'p/d']) == ['p/a', 'p/d', 'p/e']


def test_impact_all_leaves_out_leaf_nodes_and_reports_the_ratio():
    result = impact_all(_system(SYSTEM))
    rows = {r['id']: (r['rate_impact'], r['traditional_impact'])
            for r in result['nodes']}
    assert 'p/e' not in rows
    assert rows['p/a'] == (3, 5)
    rate = sum(r[0] for r in rows.values())
    traditional = sum(r[1] for r in rows.values())
    assert result['ratio'] == round(rate / traditional, 3)


def test_unknown_node_names_the_closest_ones():
    with pytest.raises(UnknownNodeError) as info:
        expand_changed(_system(SYSTEM), ['p/aa'])
    assert "unknown node 'p/aa'" in str(info.value)
    assert 'p/a' in str(info.value)


def test_remaps_match_resolved_names_in_the_node_namespace():
    remaps = [('scan', 'front/scan'), ('~out', '/global_out')]
    assert resolve('scan', node_name='n', namespace='/r',
                   remaps=remaps) == '/r/front/scan'
    # the remap matches the resolved name, however it was written
    assert resolve('/r/scan', node_name='n', namespace='/r',
                   remaps=remaps) == '/r/front/scan'
    assert resolve('out', node_name='n', namespace='/r',
                   handle_namespace='~', remaps=remaps) == '/global_out'
    # names that no remap matches are left alone
    assert resolve('other', node_name='n', namespace='/r',
                   remaps=remaps) == '/r/other'
    # the last matching remap wins
    assert resolve('a', node_name='n', remaps=[('a', 'b'), ('a', 'c')]) \
        == '/c'


_NAME_PART = '[a-z][a-z0-9_]{0,5}'


def _names():
    from hypothesis import strategies as st
    part = st.from_regex(f'\\A{_NAME_PART}\\Z')
    relative = st.lists(part, min_size=1, max_size=4).map('/'.join)
    return st.one_of(
        relative, relative.map(lambda n: '/' + n),
        relative.map(lambda n: '~' + n), relative.map(lambda n: '~/' + n))


def _namespaces():
    from hypothesis import strategies as st
    part = st.from_regex(f'\\A{_NAME_PART}\\Z')
    return st.lists(part, max_size=3).map(lambda p: '/' + '/'.join(p))


def test_resolution_properties():
    from hypothesis import given
    from hypothesis import settings
    from hypothesis import strategies as st

    @settings(max_examples=300, derandomize=True, deadline=None)
    @given(name=_names(), namespace=_namespaces(),
           node=st.from_regex(f'\\A{_NAME_PART}\\Z'),
           handle=st.sampled_from(['', '~', 'sub', '/abs', '~priv']))
    def check(name, namespace, node, handle):
        resolved = resolve(name, node_name=node, namespace=namespace,
                           handle_namespace=handle)
        # always a normalised global name
        assert resolved.startswith('/') and '//' not in resolved
        assert not resolved.endswith('/') or resolved == '/'
        # resolving a global name again changes nothing
        assert resolve(resolved, node_name='other', namespace='/x',
                       handle_namespace=handle) == resolved
        # the relative part is kept at the end
        assert resolved.endswith(name.lstrip('~').lstrip('/'))
        # private names live under the node's full name
        if name.startswith('~'):
            assert resolved.startswith(join(namespace, node) + '/')
        # a remap of the resolved name is applied, to a global target
        assert resolve(name, node_name=node, namespace=namespace,
                       handle_namespace=handle,
                       remaps=[(resolved, '/remapped')]) == '/remapped'
    check()


def test_impact_all_agrees_with_one_traversal_per_node():
    import random
    rng = random.Random(7)
    for _ in range(20):
        names = [f'n{i}' for i in range(12)]
        topics = [f't{i}' for i in range(6)]
        spec = {
            name: ([(rng.choice(topics), rng.choice([I, D]))
                    for _ in range(rng.randint(0, 2))],
                   [rng.choice(topics) for _ in range(rng.randint(0, 2))])
            for name in names}
        system = _system(spec)
        rows = {r['id']: r for r in impact_all(system)['nodes']}
        for node_id in sorted(system.instances):
            traditional = traditional_impact(system, [node_id])
            if not traditional:
                assert node_id not in rows
                continue
            assert rows[node_id]['traditional_impact'] == len(traditional)
            assert rows[node_id]['rate_impact'] == \
                len(rate_impact(system, [node_id]))


ROS1_CONTROLLERS_LAUNCH = """<launch>
  <rosparam ns="arm">
    velocity_controller:
      type: acme_controllers/VelocityController
    state_controller:
      type: joint_state_controller/JointStateController
  </rosparam>
  <group ns="arm">
    <node name="controller_spawner" pkg="controller_manager" type="spawner"
          args="--shutdown-timeout=3 velocity_controller state_controller"/>
  </group>
</launch>
"""


def test_a_ros1_spawner_loads_the_controllers_its_parameters_type(tmp_path):
    from colcon_rsia.launch import load_launch
    from colcon_rsia.system.load import launch_instances
    path = tmp_path / 'control.launch'
    path.write_text(ROS1_CONTROLLERS_LAUNCH)
    # a controller's topics go through the NodeHandle its host gives it,
    # in the controller's own namespace ('~')
    plugin = Node(
        id='acme_controllers/VelocityController', package='acme_controllers',
        executable='VelocityController', kind='plugin',
        plugin_class='acme_controllers::VelocityController',
        publishers=[LabelledPublisher(
            topic='state', topic_is_literal=True, msg_type='m', api='a',
            handle='h', namespace='~', location='f:1',
            label=INDEPENDENT, pattern='host_periodic', rate_hz=None)],
        subscribers=[NodeSubscriber(
            topic='command', topic_is_literal=True, msg_type='m', api='a',
            callback='cb', namespace='~', location='f:2')])
    summary = PackageSummary(
        package='acme_controllers', path='/a', tool_version='0',
        nodes=[plugin])
    instances, notes = launch_instances(
        [summary], load_launch(str(path), package_paths={}))
    by_id = {i.id: i for i in instances}
    # each spawned controller is a node named after it, where the spawner
    # runs; one of a package outside the workspace is not analysed
    assert set(by_id) == {'/arm/controller_spawner', '/arm/velocity_controller',
                          '/arm/state_controller'}
    assert by_id['/arm/velocity_controller'].node is plugin
    assert by_id['/arm/state_controller'].node is None
    graph = build_graph([summary], instances=instances, notes=notes)
    topics = set(graph.topics())
    assert {'/arm/velocity_controller/state',
            '/arm/velocity_controller/command'} <= topics
