# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The one place the front ends make facts.

Both front ends (:mod:`colcon_rsia.frontend.cpp`,
:mod:`colcon_rsia.frontend.python`) say what a call's arguments mean; the
fact they make of it, and the list of the unit's facts it goes to, is
made here: one function per kind of fact, taking the unit's
:class:`~colcon_rsia.frontend.facts.TuFacts` and the fact's fields, and
returning the fact recorded; :func:`unit_facts` makes the (empty) facts of
a unit. (tests/project/test_imports.py fails when a
module of either front end constructs a fact class itself.)
"""

from colcon_rsia.frontend.facts import ActionFact
from colcon_rsia.frontend.facts import Call
from colcon_rsia.frontend.facts import ClientFact
from colcon_rsia.frontend.facts import Function
from colcon_rsia.frontend.facts import HandleAlias
from colcon_rsia.frontend.facts import HostEvent
from colcon_rsia.frontend.facts import NameArgument
from colcon_rsia.frontend.facts import NodeHandleFact
from colcon_rsia.frontend.facts import NodeletLoad
from colcon_rsia.frontend.facts import NodeNameFact
from colcon_rsia.frontend.facts import PacedLoop
from colcon_rsia.frontend.facts import ParamBinding
from colcon_rsia.frontend.facts import ParamRead
from colcon_rsia.frontend.facts import PublisherFact
from colcon_rsia.frontend.facts import PublishSite
from colcon_rsia.frontend.facts import RateObject
from colcon_rsia.frontend.facts import Registration
from colcon_rsia.frontend.facts import ServiceFact
from colcon_rsia.frontend.facts import StringArgument
from colcon_rsia.frontend.facts import SubscriberFact
from colcon_rsia.frontend.facts import SyncFact
from colcon_rsia.frontend.facts import TimerFact
from colcon_rsia.frontend.facts import TuFacts


def add_function(facts, **fields):
    """Record a function or lambda of the package.

    A :class:`Function`, appended to ``facts.functions``.
    """
    fact = Function(**fields)
    facts.functions.append(fact)
    return fact


def add_call(facts, **fields):
    """Record a call (or reference) of a package function by another.

    A :class:`Call`, appended to ``facts.calls``.
    """
    fact = Call(**fields)
    facts.calls.append(fact)
    return fact


def name_argument(**fields):
    """A :class:`NameArgument`, for the call (:func:`add_call`) passing it."""
    return NameArgument(**fields)


def add_publisher(facts, **fields):
    """Record a publisher (an advertise / create_publisher call, a declared one).

    A :class:`PublisherFact`, appended to ``facts.publishers``.
    """
    fact = PublisherFact(**fields)
    facts.publishers.append(fact)
    return fact


def add_subscriber(facts, **fields):
    """Record a subscription.

    A :class:`SubscriberFact`, appended to ``facts.subscribers``.
    """
    fact = SubscriberFact(**fields)
    facts.subscribers.append(fact)
    return fact


def add_timer(facts, **fields):
    """Record a timer and the callback it calls.

    A :class:`TimerFact`, appended to ``facts.timers``.
    """
    fact = TimerFact(**fields)
    facts.timers.append(fact)
    return fact


def add_service(facts, **fields):
    """Record a service server.

    A :class:`ServiceFact`, appended to ``facts.services``.
    """
    fact = ServiceFact(**fields)
    facts.services.append(fact)
    return fact


def add_client(facts, **fields):
    """Record a service client.

    A :class:`ClientFact`, appended to ``facts.clients``.
    """
    fact = ClientFact(**fields)
    facts.clients.append(fact)
    return fact


def add_action(facts, **fields):
    """Record an action server or client.

    A :class:`ActionFact`, appended to ``facts.actions``.
    """
    fact = ActionFact(**fields)
    facts.actions.append(fact)
    return fact


def add_publish_site(facts, **fields):
    """Record a publish call through a handle.

    A :class:`PublishSite`, appended to ``facts.publish_sites``.
    """
    fact = PublishSite(**fields)
    facts.publish_sites.append(fact)
    return fact


def add_rate(facts, **fields):
    """Record a rate object (Rate, a deadline advanced in its loop).

    A :class:`RateObject`, appended to ``facts.rates``.
    """
    fact = RateObject(**fields)
    facts.rates.append(fact)
    return fact


def add_paced_loop(facts, **fields):
    """Record a loop a sleep paces (see recorder.record_paced_loop).

    A :class:`PacedLoop`, appended to ``facts.paced_loops``.
    """
    fact = PacedLoop(**fields)
    facts.paced_loops.append(fact)
    return fact


def add_sync(facts, **fields):
    """Record a message synchroniser and its inputs.

    A :class:`SyncFact`, appended to ``facts.syncs``.
    """
    fact = SyncFact(**fields)
    facts.syncs.append(fact)
    return fact


def add_registration(facts, **fields):
    """Record a callback registered with an object of the API.

    A :class:`Registration`, appended to ``facts.registrations``.
    """
    fact = Registration(**fields)
    facts.registrations.append(fact)
    return fact


def add_host_event(facts, **fields):
    """Record a callback of the hosting process's events.

    A :class:`HostEvent`, appended to ``facts.host_events``.
    """
    fact = HostEvent(**fields)
    facts.host_events.append(fact)
    return fact


def add_nodelet_load(facts, **fields):
    """Record a nodelet loaded in code.

    A :class:`NodeletLoad`, appended to ``facts.nodelet_loads``.
    """
    fact = NodeletLoad(**fields)
    facts.nodelet_loads.append(fact)
    return fact


def add_node_name(facts, **fields):
    """Record the node's name (and namespace) as the code gives it.

    A :class:`NodeNameFact`, appended to ``facts.node_names``.
    """
    fact = NodeNameFact(**fields)
    facts.node_names.append(fact)
    return fact


def add_node_handle(facts, **fields):
    """Record a NodeHandle / sub-node and its namespace.

    A :class:`NodeHandleFact`, appended to ``facts.node_handles``.
    """
    fact = NodeHandleFact(**fields)
    facts.node_handles.append(fact)
    return fact


def add_param_read(facts, **fields):
    """Record a parameter read.

    A :class:`ParamRead`, appended to ``facts.param_reads``.
    """
    fact = ParamRead(**fields)
    facts.param_reads.append(fact)
    return fact


def add_handle_alias(facts, **fields):
    """Record a variable that is another handle.

    A :class:`HandleAlias`, appended to ``facts.handle_aliases``.
    """
    fact = HandleAlias(**fields)
    facts.handle_aliases.append(fact)
    return fact


def add_binding(facts, **fields):
    """Record a handle a call passes to a package function's parameter.

    A :class:`ParamBinding`, appended to ``facts.bindings``.
    """
    fact = ParamBinding(**fields)
    facts.bindings.append(fact)
    return fact


def add_string_argument(facts, **fields):
    """Record a string literal a call passes to a package function.

    A :class:`StringArgument`, appended to ``facts.string_arguments``.
    """
    fact = StringArgument(**fields)
    facts.string_arguments.append(fact)
    return fact


def unit_facts(source, **fields):
    """The facts of one unit (its main file `source`), none found yet."""
    return TuFacts(source=source, **fields)
