# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The closed vocabularies of the summary: labels, patterns, kinds, marks.

The values a summary's fields take from a fixed set: the label and pattern
of a publisher edge, the kind of a root, where a fact comes from, and the
marks of what the analysis could not know. Facts (build time) and the
summary share them.
"""

# labels and patterns of a publisher edge (the paper's Algorithm 1)
INDEPENDENT = 'independent'
DEPENDENT = 'dependent'
PATTERN_NO_SUBSCRIBERS = 'no_subscribers'
PATTERN_TIMER = 'timer'
PATTERN_RATE_LOOP = 'rate_loop'
PATTERN_MIXED = 'mixed'
PATTERN_NONE = 'none'
# a plugin's publish reached only from a method its host calls from its own
# fixed-rate loop (a controller's update())
PATTERN_HOST_PERIODIC = 'host_periodic'

# root kinds
ROOT_MAIN = 'main'
ROOT_NODELET = 'nodelet'
ROOT_SUBSCRIBER = 'subscriber'
ROOT_TIMER = 'timer'
ROOT_SERVICE = 'service'
ROOT_ACTION = 'action'
ROOT_ENTRY = 'entry'  # a function nobody calls: entered from outside
# a publisher's callback run when a subscriber connects or disconnects
ROOT_CONNECT = 'connect'
# a plugin's methods its host calls (colcon_rsia.package.plugin_hosts)
ROOT_HOST_PERIODIC = 'host_periodic'
ROOT_HOST_REQUEST = 'host_request'
ROOT_HOST_SETUP = 'host_setup'

# the mark of a NodeHandle namespace the code builds from a value the
# analysis does not know (`ros::NodeHandle nh(real_name)`), followed by the
# expression as written: names relative to it are not resolved
UNKNOWN_NAMESPACE = '?'

# where a fact comes from: the AST, or the tokens of a call the parse lost
# (colcon_rsia.frontend.cpp.token_facts)
ORIGIN_AST = 'ast'
ORIGIN_TOKENS = 'tokens'

# the trigger standing for every input of the node (Trigger.kind)
TRIGGER_ALL = 'all'
