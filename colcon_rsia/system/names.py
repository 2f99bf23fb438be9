# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""ROS name resolution: global, relative and private names, and remaps.

ROS 1 and ROS 2 agree on what matters here: a relative name is resolved in
the namespace of the handle that uses it (the node's namespace, a private
``~`` handle's node name, or a sub-namespace), ``~x`` and ``~/x`` are
private to the node, and a remap replaces a resolved name by another; both
sides of a remap are resolved in the node's namespace.
"""

from colcon_rsia.launch.common import normalise_ns
from colcon_rsia.summary.kinds import UNKNOWN_NAMESPACE


def join(namespace, name):
    """Join a namespace and a relative name into a normalised global name.

    The launch readers normalise names the same way (``normalise_ns``);
    one definition keeps the names they give and the ones resolved here
    equal.
    """
    return normalise_ns(f'{namespace}/{name}')


def node_fqn(namespace, node_name):
    """The fully qualified name of a node (``/ns/name``)."""
    return join(namespace or '/', node_name)


def _expand(name, *, fqn, base):
    if name.startswith('/'):
        return join('/', name)
    if name.startswith('~'):
        return join(fqn, name[1:])
    return join(base, name)


def resolve(name, *, node_name, namespace='/', handle_namespace='',
            remaps=()):
    """Resolve a topic name as ROS does for a handle of a node.

    :param str name: the name as written (None when not known)
    :param str node_name: the node's base name
    :param str namespace: the node's namespace
    :param str handle_namespace: the NodeHandle's namespace: '' (the
      node's), '~' or '~sub' (private), a relative or a global namespace
    :param remaps: (from, to) pairs as written for the node; later ones win
    :returns: the global name, or None when the name is not known
    """
    if name is None or name == '':
        return None
    if (handle_namespace or '').startswith(UNKNOWN_NAMESPACE) and \
            not name.startswith(('/', '~')):
        return None  # relative to a namespace the code computes
    namespace = namespace or '/'
    fqn = node_fqn(namespace, node_name)
    base = namespace
    if handle_namespace:
        base = _expand(handle_namespace, fqn=fqn, base=namespace)
    resolved = _expand(name, fqn=fqn, base=base)
    for source, target in reversed(list(remaps)):
        if _expand(source, fqn=fqn, base=namespace) == resolved:
            return _expand(target, fqn=fqn, base=namespace)
    return resolved
