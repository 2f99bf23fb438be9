# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""ROS name resolution: global, relative and private names."""


def join(namespace, name):
    """Join a namespace and a relative name into a normalised global name."""
    parts = [p for p in f'{namespace}/{name}'.split('/') if p]
    return '/' + '/'.join(parts)


def node_fqn(namespace, node_name):
    """The fully qualified name of a node (``/ns/name``)."""
    return join(namespace or '/', node_name)


def resolve(name, *, node_name, namespace='/', handle_namespace=''):
    """Resolve a topic name as ROS does for a handle of a node.

    :param str name: the name as written (None when not known)
    :param str node_name: the node's base name
    :param str namespace: the node's namespace
    :param str handle_namespace: the NodeHandle's namespace: '' (the
      node's), '~' (private), a relative or a global namespace
    :returns: the global name, or None when the name is not known
    """
    if name is None or name == '':
        return None
    fqn = node_fqn(namespace, node_name)
    if name.startswith('/'):
        return join('/', name)
    if name.startswith('~'):
        return join(fqn, name[1:])
    base = namespace or '/'
    if handle_namespace:
        if handle_namespace.startswith('~'):
            base = join(fqn, handle_namespace[1:])
        elif handle_namespace.startswith('/'):
            base = handle_namespace
        else:
            base = join(base, handle_namespace)
    return join(base, name)
