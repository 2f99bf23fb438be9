# Not a node: the analysis skips test/ (and would fail loudly if it ran this).
raise RuntimeError('test modules are never part of a node')
