# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The C++ front end: a libclang walk from a translation unit to its facts.

Only cursors whose file lies inside the package are walked (a TU with the
real ROS headers has ~400k cursors; the package's own code a few thousand).
A ROS call is recognised by the qualified name of the declaration it calls,
looked up in :mod:`colcon_rsia.frontend.ros_api`.
"""

import dataclasses
import os
import re

import clang.cindex as ci
from colcon_rsia import model
from colcon_rsia.frontend import clocks
from colcon_rsia.frontend import ros_api
from colcon_rsia.frontend import wrappers
from colcon_rsia.frontend.const_eval import evaluate_duration_seconds
from colcon_rsia.frontend.const_eval import evaluate_number
from colcon_rsia.frontend.const_eval import is_chrono_duration
from colcon_rsia.frontend.const_eval import source_tokens
from colcon_rsia.frontend.cursors import call_object
from colcon_rsia.frontend.cursors import child_cursors
from colcon_rsia.frontend.cursors import CLASS_KINDS
from colcon_rsia.frontend.cursors import explicit_template_type
from colcon_rsia.frontend.cursors import expression_text
from colcon_rsia.frontend.cursors import first_function
from colcon_rsia.frontend.cursors import first_handle
from colcon_rsia.frontend.cursors import first_template_argument
from colcon_rsia.frontend.cursors import FUNCTION_KINDS
from colcon_rsia.frontend.cursors import HANDLE_KINDS
from colcon_rsia.frontend.cursors import LOOP_KINDS
from colcon_rsia.frontend.cursors import normalize_msg_type
from colcon_rsia.frontend.cursors import qualified_name
from colcon_rsia.frontend.cursors import REF_KINDS
from colcon_rsia.frontend.cursors import same_cursor
from colcon_rsia.frontend.cursors import SCOPE_KINDS
from colcon_rsia.frontend.cursors import STATEMENT_KINDS
from colcon_rsia.frontend.cursors import VALUE_FUNCTION_KINDS
from colcon_rsia.frontend.cursors import walk_preorder
from colcon_rsia.frontend.every_nth import every_nth
from colcon_rsia.frontend.model_mode import MODEL_HEADERS_DIR
from colcon_rsia.model import UNKNOWN_NAMESPACE

CK = ci.CursorKind

# plugin registrations, read from the source text: a detailed processing
# record would show them as macro instantiations, but it triples the number
# of top-level cursors (every macro of every header) and so the walk time
EXPORT_MACRO = re.compile(
    r'\b(?:PLUGINLIB_EXPORT_CLASS|CLASS_LOADER_REGISTER_CLASS)\s*\(\s*'
    r'([\w:]+(?:\s*<[^;()]*?>)?)\s*,\s*([\w:]+(?:\s*<[^;()]*>)?)\s*\)')
COMPONENT_MACRO = re.compile(
    r'\bRCLCPP_COMPONENTS_REGISTER_NODE\s*\(\s*([\w:]+)\s*\)')
# the base recorded for a registered ROS 2 component
COMPONENT_BASE = 'rclcpp::Node'
# behavior-tree nodes a plugin library registers for a BT executor
# (navigation2's bt_navigator): `BT_REGISTER_NODES(factory) { ...
# factory.registerNodeType<ns::Class>("Name"); }`
BT_REGISTRATION = re.compile(r'\bBT_REGISTER_NODES\s*\(\s*(\w+)\s*\)')
BT_NODE_TYPE = re.compile(r'\bregisterNodeType\s*<\s*([\w:]+)\s*>')
# the base recorded for them (the table's key: plugin_hosts.py)
BT_NODE_BASE = 'BT::TreeNode'

# incomplete: we never need the TU's template instantiations at its end
PARSE_OPTIONS = ci.TranslationUnit.PARSE_INCOMPLETE

# how many parse errors of one TU are kept in the summary
MAX_DIAGNOSTICS_PER_TU = 5


_SMART_POINTER = re.compile(r'^(?:std|boost)::(?:shared_ptr|unique_ptr)<')


class _MemberInit:
    """Stands on the expression stack for a constructor's member init."""

    kind = None

    def __init__(self, member):
        self.member = member


def parse(index, *, file, arguments, resource_dir, working_directory,
          unsaved_files=()):
    """Parse one translation unit with libclang.

    :param unsaved_files: (path, content) pairs read instead of the files

    :raises clang.cindex.TranslationUnitLoadError: when libclang gives up
    """
    args = list(arguments)
    if resource_dir:
        args += ['-resource-dir', resource_dir]
    # the default limit of 20 errors truncates the AST
    args += ['-ferror-limit=0', '-working-directory', working_directory]
    return index.parse(file, args=args, unsaved_files=list(unsaved_files),
                       options=PARSE_OPTIONS)


def parse_diagnostics(tu):
    """Return the first parse errors of a TU as one-line strings."""
    messages = []
    for diag in tu.diagnostics:
        if diag.severity >= ci.Diagnostic.Error:
            loc = diag.location
            where = f'{loc.file.name}:{loc.line}' if loc.file else '?'
            messages.append(f'{where}: {diag.spelling}')
            if len(messages) >= MAX_DIAGNOSTICS_PER_TU:
                break
    return messages


def error_diagnostics(tu):
    """(message, file, line, column) of every error of a parsed unit."""
    errors = []
    for diag in tu.diagnostics:
        if diag.severity >= ci.Diagnostic.Error:
            loc = diag.location
            errors.append((diag.spelling, loc.file.name if loc.file else None,
                           loc.line, loc.column))
    return errors


def extract_facts(tu, *, package_path, source):
    """Walk the package's own code in a parsed TU and return its facts.

    :param tu: the parsed translation unit
    :param str package_path: absolute path of the package source
    :param str source: the TU's main file, relative to the package
    :rtype: colcon_rsia.model.TuFacts
    """
    walker = _Walker(package_path, model.TuFacts(source=source))
    walker.walk(tu)
    walker.facts.diagnostics = walker.problems + walker.facts.diagnostics
    return walker.facts


BIND_FUNCTIONS = frozenset({'boost::bind', 'std::bind'})

# the option objects roscpp's subscribe/advertise also take
_OPTIONS_TYPES = frozenset({'ros::SubscribeOptions', 'ros::AdvertiseOptions'})


def _overload_candidate(call):
    """The callee of a call libclang left unresolved, when unambiguous.

    A broken argument (a field a stand-in lacks) leaves the call's
    overload set unresolved; when every candidate has the same qualified
    name, the call is still that API.
    """
    children = child_cursors(call)
    if not children:
        return None
    for current in [children[0]] + list(walk_preorder(children[0])):
        if current.kind != CK.OVERLOADED_DECL_REF:
            continue
        count = ci.conf.lib.clang_getNumOverloadedDecls(current)
        candidates = [ci.conf.lib.clang_getOverloadedDecl(current, i)
                      for i in range(count)]
        names = {qualified_name(c) for c in candidates}
        if candidates and len(names) == 1:
            return candidates[0]
        return None
    return None


def _made_class(call):
    """The declaration of X in a ``make_shared<X>(...)`` call, or None."""
    made = call.type.get_canonical()
    if made.get_num_template_arguments() < 1:
        return None
    declaration = made.get_template_argument_type(0).get_declaration()
    if declaration is None or declaration.kind == CK.NO_DECL_FOUND:
        return None
    return declaration


class _Walker:
    """Collects the facts of one TU; see :func:`extract_facts`."""

    def __init__(self, package_path, facts):
        self.package_path = package_path.rstrip('/') + '/'
        self.facts = facts
        self._in_package_cache = {}
        # (file, offset) of expressions used as a registered callback, so
        # that they do not also count as a plain function reference
        self._consumed = set()
        self._lambdas_in_variables = set()
        self._registered = set()
        self._ros2 = False
        # callables stored in std::function variables/fields:
        # {variable USR: function ids assigned to it}
        self._callables = {}
        # string variables/fields: the literals they are set to, and those
        # also set otherwise (see _resolve_string_names)
        self._string_values = {}
        self._string_written = set()
        # (service fact, variable its name is read from)
        self._named_by_variable = []
        # NodeHandles made from a string variable: (fact, its USR)
        self._namespaced_by_variable = []
        # endpoint facts whose topic is built by `+`: (fact, parts)
        self._concatenated = []
        # declarations whose walk failed: one line each, the rest goes on
        self.problems = []
        # the workspace's wrapper functions this unit calls
        self._wrappers = wrappers.Summaries(self)
        # Qt and boost::asio timers, sleep_until loops
        self._clocks = clocks.OtherClocks(self)
        # what each role of ros_api does to the facts
        self._handlers = {
            ros_api.PUBLISHER: self._on_publisher,
            ros_api.SUBSCRIBER: self._on_subscriber,
            ros_api.TIMER: self._on_timer,
            ros_api.SERVICE: self._on_service,
            ros_api.CLIENT: self._on_client,
            ros_api.PUBLISH: self._on_publish,
            ros_api.RATE: self._on_rate,
            ros_api.RATE_SLEEP: self._on_rate_sleep,
            ros_api.SYNC: self._on_sync,
            ros_api.REGISTER_CALLBACK: self._on_register_callback,
            ros_api.ACTION_SERVER: self._on_action_server,
            ros_api.ACTION_CLIENT: self._on_action_client,
            ros_api.NODE_HANDLE: self._on_node_handle,
            ros_api.PRIVATE_HANDLE: self._on_private_handle,
            ros_api.PUBLIC_HANDLE: self._on_public_handle,
            ros_api.PARAM_READ: self._on_param_read,
            ros_api.NODE_NAME: self._on_node_name,
            ros_api.SUB_NODE: self._on_sub_node,
            ros_api.TIMED_PUBLISHER: self._on_timed_publisher,
            **self._clocks.handlers(),
        }

    # --- locations ---------------------------------------------------------

    def in_package(self, cursor):
        file = cursor.location.file
        if file is None:
            return False
        name = file.name
        cached = self._in_package_cache.get(name)
        if cached is None:
            cached = os.path.abspath(name).startswith(self.package_path)
            self._in_package_cache[name] = cached
        return cached

    def is_workspace_declaration(self, cursor):
        """Whether a declaration is in another package of the workspace.

        Its body is the workspace's code: not a system, model or stand-in
        header.
        """
        file = cursor.location.file
        if file is None:
            return False
        name = os.path.abspath(file.name)
        return not name.startswith(('/usr/', '/opt/', MODEL_HEADERS_DIR)) \
            and '/rsia/stubs/' not in name and '/rsia_model/' not in name

    def relpath(self, cursor):
        name = os.path.abspath(cursor.location.file.name)
        if name.startswith(self.package_path):
            return name[len(self.package_path):]
        return name

    def location(self, cursor):
        if cursor.location.file is None:
            return '?:0'
        return f'{self.relpath(cursor)}:{cursor.location.line}'

    def key(self, cursor):
        file = cursor.location.file
        return (file.name if file else '', cursor.extent.start.offset)

    def loop_id(self, cursor):
        return f'{self.relpath(cursor)}@{cursor.extent.start.offset}'

    # --- declarations ------------------------------------------------------

    def walk(self, tu):
        self._plugin_exports(tu.spelling)
        # a ROS 2 unit: some APIs (diagnostic_updater) keep their ROS 1
        # names but behave differently
        self._ros2 = any(
            c.kind == CK.NAMESPACE and c.spelling == 'rclcpp'
            for c in tu.cursor.get_children())
        for cursor in tu.cursor.get_children():
            if self.in_package(cursor):
                self._declaration(cursor)
        if len(self.problems) > MAX_DIAGNOSTICS_PER_TU:
            lost = len(self.problems) - MAX_DIAGNOSTICS_PER_TU
            del self.problems[MAX_DIAGNOSTICS_PER_TU:]
            self.problems.append(f'... and {lost} more declarations skipped')
        # a lambda stored in a variable and then registered as a callback
        # is a root, not something its defining function calls
        self.facts.calls = [
            c for c in self.facts.calls
            if not (c.kind == 'ref' and c.callee in self._registered and
                    c.callee in self._lambdas_in_variables)]
        self._clocks.finish()
        self._resolve_stored_callbacks()
        self._resolve_string_names()

    def _string_assignment(self, variable, expression):
        """Note what a string variable/field is set to."""
        if not _is_string(variable):
            return
        value, literal = self.topic(expression)
        if literal:
            self._string_values.setdefault(
                variable.get_usr(), set()).add(value)
        else:
            self._string_written.add(variable.get_usr())

    def _resolve_string_names(self):
        """A name held in a string set only to one literal is that literal.

        ``std::string topic_name_ = "chatter";`` (or set in the
        constructor) then ``create_subscription<M>(topic_name_, ...)``. A
        variable also set otherwise, read from a parameter or handed to a
        function of the package is left as written.
        """
        written = self._string_written | {
            r.handle for r in self.facts.param_reads if r.handle} | {
            b.handle for b in self.facts.bindings}

        def value(handle):
            values = self._string_values.get(handle)
            if handle in written or not values or len(values) != 1:
                return None
            return next(iter(values))
        for fact in self.facts.publishers + self.facts.subscribers:
            # (a topic joined around a variable: see _concatenated below)
            topic = None if fact.topic_is_literal or fact.topic_affixes \
                else value(fact.topic_handle)
            if topic:
                fact.topic = topic
                fact.topic_is_literal = True
                fact.topic_handle = None
        for fact, handle in self._named_by_variable:
            fact.name = value(handle) or fact.name
        for fact, handle in self._namespaced_by_variable:
            fact.namespace = value(handle) or fact.namespace
        for fact, parts in self._concatenated:
            values = [text if kind == 'literal' else value(text)
                      for kind, text in parts]
            if None not in values:
                fact.topic = ''.join(values)
                fact.topic_is_literal = True
                fact.topic_handle = None

    def _resolve_stored_callbacks(self):
        """Replace ``callable:<usr>`` callbacks by what was stored there.

        A callback kept in a ``std::function`` member is registered by
        naming the member; the function is what the code assigned to it
        (anywhere in the TU, before or after the registration).
        """
        def resolve(callback):
            if callback and callback.startswith(CALLABLE_PREFIX):
                stored = self._callables.get(callback[len(CALLABLE_PREFIX):])
                return sorted(stored)[0] if stored else None
            return callback
        for fact in (self.facts.subscribers + self.facts.timers +
                     self.facts.services + self.facts.registrations):
            fact.callback = resolve(fact.callback)
        for fact in self.facts.actions:
            fact.callbacks = [c for c in map(resolve, fact.callbacks) if c]

    def _declaration(self, cursor):
        try:
            kind = cursor.kind
        except ValueError:
            return  # a cursor kind this libclang binding does not know
        if kind in SCOPE_KINDS:
            if kind in CLASS_KINDS:
                self._class_bases(cursor)
            for child in cursor.get_children():
                if self.in_package(child):
                    self._declaration(child)
            return
        if kind in (CK.TYPEDEF_DECL, CK.TYPE_ALIAS_DECL):
            self._class_alias(cursor)
            return
        # what invalid code leaves in the AST may surprise any rule below:
        # such a declaration loses its own facts, never the unit's
        try:
            if kind in FUNCTION_KINDS:
                if cursor.is_definition():
                    self._function(cursor)
            elif kind in (CK.FIELD_DECL, CK.VAR_DECL):
                self._declared_object(cursor, function=None)
                self._initialized_string(cursor)
        except Exception as e:  # noqa: B902
            self.problems.append(
                f'{self.location(cursor)}: {cursor.spelling or kind.name} '
                f'not analysed (internal error: {type(e).__name__}: {e}); '
                'please report it')

    def _plugin_exports(self, main_file):
        try:
            with open(main_file, encoding='utf-8', errors='replace') as h:
                text = h.read()
        except OSError:
            return
        for match in EXPORT_MACRO.finditer(text):
            self.facts.plugin_exports.append(
                [match.group(1).lstrip(':'), match.group(2).lstrip(':')])
        for match in COMPONENT_MACRO.finditer(text):
            self.facts.plugin_exports.append(
                [match.group(1).lstrip(':'), COMPONENT_BASE])
        registration = BT_REGISTRATION.search(text)
        if registration is not None:
            for match in BT_NODE_TYPE.finditer(text, registration.end()):
                self.facts.plugin_exports.append(
                    [match.group(1).lstrip(':'), BT_NODE_BASE])

    def _class_bases(self, cursor):
        """Record the bases of a package class (a plugin inherits methods)."""
        name = qualified_name(cursor)
        for child in cursor.get_children():
            if child.kind != CK.CXX_BASE_SPECIFIER:
                continue
            base = child.type.get_declaration()
            if base is not None and base.kind != CK.NO_DECL_FOUND:
                base_name = qualified_name(base)
            else:
                base_name = re.sub(r'<.*', '', child.type.spelling)
            if base_name and [name, base_name] not in self.facts.class_bases:
                self.facts.class_bases.append([name, base_name])

    def _class_alias(self, cursor):
        """``typedef Controller<Iface> JointController;`` names a class."""
        target = cursor.underlying_typedef_type.get_canonical()
        declaration = target.get_declaration()
        if declaration is None or declaration.kind not in CLASS_KINDS:
            return
        # a template's specialisation has the template's qualified name
        self.facts.class_aliases.append(
            [qualified_name(cursor), qualified_name(declaration)])

    def _class_id(self, cursor):
        parent = cursor.semantic_parent
        if parent is not None and parent.kind in CLASS_KINDS:
            return parent.get_usr()
        return None

    def _function(self, cursor):
        fid = cursor.get_usr()
        self.facts.functions.append(model.Function(
            id=fid, name=qualified_name(cursor),
            location=self.location(cursor),
            class_id=self._class_id(cursor),
            params=[c.get_usr() for c in cursor.get_children()
                    if c.kind == CK.PARM_DECL]))
        parent = cursor.semantic_parent
        ctx = _Context(fid, owner=parent if parent is not None and
                       parent.kind in CLASS_KINDS else None)
        pending_member = None
        for child in cursor.get_children():
            if child.kind == CK.MEMBER_REF:
                pending_member = child.referenced
                continue
            if child.kind in (CK.PARM_DECL, CK.TYPE_REF, CK.NAMESPACE_REF,
                              CK.TEMPLATE_REF, CK.TEMPLATE_TYPE_PARAMETER,
                              CK.TEMPLATE_NON_TYPE_PARAMETER):
                continue
            stack = [_MemberInit(pending_member)] if pending_member else []
            if pending_member is not None and _is_callable(pending_member):
                self._store_callable(pending_member, child)
            if pending_member is not None:
                self._string_assignment(pending_member, child)
            self._visit(child, ctx, stack)
            pending_member = None

    def _declared_object(self, cursor, function):
        """A variable or field whose type makes it a publisher/listener."""
        if cursor.type.kind in (ci.TypeKind.LVALUEREFERENCE,
                                ci.TypeKind.RVALUEREFERENCE):
            return
        spellings = cursor.type.spelling + ' ' + \
            cursor.type.get_canonical().spelling
        for class_name, api in ros_api.DECLARED.items():
            if not re.search(
                    r'(?<![\w:])' + re.escape(class_name) + r'(?!\w)',
                    spellings):
                continue
            class_id = self._class_id(cursor) if function is None else None
            for topic in api.implicit_topics:
                common = dict(
                    function=function, api=class_name, topic=topic,
                    topic_is_literal=True,
                    msg_type=self._table_msg_type(api.msg_type),
                    handle=cursor.get_usr(), location=self.location(cursor),
                    class_id=class_id)
                if api.role == ros_api.DECLARED_PUBLISHER:
                    self.facts.publishers.append(model.PublisherFact(
                        handle_name=cursor.spelling, **common))
                else:
                    self.facts.subscribers.append(model.SubscriberFact(
                        callback=None, **common))
            return

    # --- function bodies ---------------------------------------------------

    def _visit(self, cursor, ctx, stack):
        kind = cursor.kind
        if kind == CK.LAMBDA_EXPR:
            self._lambda(cursor, ctx)
            return
        if kind == CK.CALL_EXPR:
            self._call(cursor, ctx, stack)
        elif kind in REF_KINDS:
            self._reference(cursor, ctx, stack)
        elif kind == CK.VAR_DECL:
            self._declared_object(cursor, ctx.function)
            self._copied_handle(cursor)
            self._initialized_string(cursor)
            init = _initializer(cursor)
            if init is not None and init.kind == CK.LAMBDA_EXPR:
                self._lambdas_in_variables.add(self._lambda_id(init))
            elif init is not None and _is_callable(cursor):
                self._store_callable(cursor, init)
        children = child_cursors(cursor)
        stack.append(cursor)
        if kind in LOOP_KINDS:
            ctx.loops.append((self.loop_id(cursor), ctx.conditional, cursor))
            for child in children:
                self._visit(child, ctx, stack)
            ctx.loops.pop()
        elif children and (
                kind in (CK.IF_STMT, CK.SWITCH_STMT, CK.CONDITIONAL_OPERATOR,
                         CK.CXX_TRY_STMT) or
                kind == CK.BINARY_OPERATOR and _is_logical(cursor, children)):
            # the condition (the try block, the left operand) runs every
            # time; the branches (the handlers, the right operand) may not
            self._visit(children[0], ctx, stack)
            ctx.conditional += 1
            for child in children[1:]:
                self._visit(child, ctx, stack)
            ctx.conditional -= 1
        else:
            for child in children:
                self._visit(child, ctx, stack)
        stack.pop()

    def _initialized_string(self, variable):
        init = _initializer(variable)
        if init is not None:
            self._string_assignment(variable, init)

    def _copied_handle(self, variable):
        """``auto pub = pub_;``: the local copy publishes through `pub_`.

        So do ``std::weak_ptr<P> weak = pub_;`` and ``auto p = weak.lock();``.
        """
        init = _initializer(variable)
        if init is None:
            return
        tokens = [t.spelling for t in source_tokens(init)]
        # a weak_ptr's lock() or a smart pointer's get() is the same object
        if tokens[-4:] in (['.', 'lock', '(', ')'], ['.', 'get', '(', ')']):
            tokens = tokens[:-4]
        # only a plain name (this->pub_, self.pub_): no call, no index
        if not tokens or any(t in ('(', '[', '{') for t in tokens):
            return
        handle = first_handle(init)
        # the package's own handles: not the fields of a message
        if handle is not None and handle != variable and \
                self.in_package(handle):
            self.facts.handle_aliases.append(model.HandleAlias(
                alias=variable.get_usr(), handle=handle.get_usr(),
                location=self.location(variable)))

    def _lambda_id(self, cursor):
        loc = cursor.location
        return f'lambda@{self.relpath(cursor)}:{loc.line}:{loc.column}'

    def _lambda(self, cursor, ctx):
        lid = self._lambda_id(cursor)
        self.facts.functions.append(model.Function(
            id=lid, name=f'lambda@{self.location(cursor)}',
            location=self.location(cursor),
            class_id=None,
            params=[c.get_usr() for c in cursor.get_children()
                    if c.kind == CK.PARM_DECL]))
        if self.key(cursor) not in self._consumed:
            self._add_call(ctx, lid, cursor, kind='ref')
        inner = _Context(lid, owner=ctx.owner)
        for child in cursor.get_children():
            if child.kind == CK.COMPOUND_STMT:
                self._visit(child, inner, [])

    def _add_call(self, ctx, callee, cursor, kind='call'):
        self.facts.calls.append(model.Call(
            caller=ctx.function, callee=callee,
            location=self.location(cursor), loops=ctx.loop_ids(), kind=kind))

    def _reference(self, cursor, ctx, stack):
        """A function named but not called here: it may be called later."""
        ref = cursor.referenced
        if ref is None or ref.kind not in FUNCTION_KINDS or \
                not self.in_package(ref):
            return
        if self.key(cursor) in self._consumed:
            return
        for parent in stack[-2:]:
            if getattr(parent, 'kind', None) == CK.CALL_EXPR and \
                    same_cursor(parent.referenced, ref):
                return  # the callee of a call, counted by _call
        self._add_call(ctx, ref.get_usr(), cursor, kind='ref')

    def _store_callable(self, variable, expression):
        """Remember what a std::function variable/field is set to."""
        callback, _ = self.resolve_callback(expression)
        if callback and not callback.startswith(CALLABLE_PREFIX):
            self._callables.setdefault(variable.get_usr(), set()).add(
                callback)

    def _call(self, cursor, ctx, stack):
        ref = cursor.referenced
        if ref is None:
            ref = _overload_candidate(cursor)
        if ref is None:
            self._dependent_call(cursor, ctx, stack)
            return
        if cursor.spelling == 'operator=':
            children = child_cursors(cursor)
            target = first_handle(children[0]) if children else None
            if target is not None and _is_callable(target):
                self._store_callable(target, children[-1])
            elif target is not None and len(children) > 1:
                self._string_assignment(target, children[-1])
        if ref.kind in FUNCTION_KINDS and self.in_package(ref):
            self._add_call(ctx, ref.get_usr(), cursor)
            self._bind_arguments(ref.get_usr(), cursor.get_arguments(),
                                 caller=ctx.function)
            return
        name = qualified_name(ref)
        api = ros_api.lookup_call(name)
        arguments = None
        if api is None and name in ros_api.FORWARDING_FACTORIES:
            self._forwarded_package_constructor(cursor, ctx)
            name, api = self._forwarded_constructor(cursor)
        if api is None:
            if ref.kind in FUNCTION_KINDS and \
                    self.is_workspace_declaration(ref):
                self._wrapper_call(cursor, ctx, stack, ref)
            return
        arguments = list(cursor.get_arguments())
        self._handlers[api.role](cursor, ctx, stack, api, name, arguments)

    def _dependent_call(self, cursor, ctx, stack):
        """``node->template create_publisher<M>(...)`` in a template.

        On an object of a template parameter's type (``NodeT node``) the
        call resolves only when the template is instantiated, which the
        AST does not show: the endpoint-creating methods are recognised by
        their name (see ros_api.DEPENDENT_METHODS).
        """
        name = self.dependent_call_name(cursor)
        if name is None:
            return
        api = ros_api.lookup_call(name)
        self._handlers[api.role](
            cursor, ctx, stack, api, name, list(cursor.get_arguments()))

    def dependent_call_name(self, cursor):
        """The API a call on a template-dependent object names, or None."""
        children = child_cursors(cursor)
        if not children or children[0].kind != CK.MEMBER_REF_EXPR:
            return None
        # a dependent member has no spelling: the name follows `.`/`->`
        tokens = [t.spelling for t in source_tokens(children[0])]
        accesses = [i for i, t in enumerate(tokens) if t in ('.', '->')]
        if not accesses:
            return None
        rest = [t for t in tokens[accesses[-1] + 1:] if t != 'template']
        if not rest:
            return None
        return ros_api.dependent_method(rest[0], ros2=self._ros2)

    def _wrapper_call(self, cursor, ctx, stack, ref):
        """A call of a workspace wrapper: the facts its summary gives.

        See :mod:`colcon_rsia.frontend.wrappers`. An endpoint the wrapper
        keeps in a member of a helper object is the handle
        ``<object>|<member>``, which the object's publishing methods
        publish through.
        """
        summary = self._wrappers.of(ref)
        if not summary.endpoints and not summary.publishes_members:
            return
        arguments = list(cursor.get_arguments())
        target = self.target(cursor, stack)
        obj = first_handle(call_object(cursor))
        name = qualified_name(ref)
        written = explicit_template_type(cursor) or \
            first_template_argument(cursor.type.get_canonical().spelling)
        location = self.location(cursor)
        # the helper object the wrapper's members belong to
        holder = target if ref.kind == CK.CONSTRUCTOR else obj

        def argument(index):
            return arguments[index] \
                if index is not None and index < len(arguments) else None
        for endpoint in summary.endpoints:
            if endpoint.topic_param is not None:
                topic, literal = self.topic(argument(endpoint.topic_param))
            else:
                topic, literal = endpoint.topic, endpoint.topic_is_literal
            msg_type = endpoint.msg_type or (
                normalize_msg_type(written)
                if endpoint.msg_type_from_call else None)
            if endpoint.member is not None and holder is not None:
                handle = f'{holder.get_usr()}|{endpoint.member}'
            elif target is not None and endpoint.member is None:
                handle = target.get_usr()
            else:
                handle = f'wrapper@{location}'
            common = dict(
                function=ctx.function, api=name, topic=topic,
                topic_is_literal=literal, msg_type=msg_type, handle=handle,
                location=location)
            if endpoint.role == wrappers.ROLE_PUBLISHER:
                self.facts.publishers.append(model.PublisherFact(
                    handle_name=target.spelling if target is not None
                    else None, **common))
            else:
                callback, declaration = self.resolve_callback(
                    argument(endpoint.callback_param))
                # a message type the wrapper deduces from the callback
                common['msg_type'] = common['msg_type'] or \
                    self._callback_msg_type(declaration)
                self.facts.subscribers.append(model.SubscriberFact(
                    callback=callback, **common))
            if endpoint.publishes:
                self._publish_site(ctx, stack, cursor, name, handle)
        if obj is not None:
            for member in sorted(summary.publishes_members):
                self._publish_site(ctx, stack, cursor, name,
                                   f'{obj.get_usr()}|{member}')

    def _publish_site(self, ctx, stack, cursor, api, handle):
        self.facts.publish_sites.append(model.PublishSite(
            function=ctx.function, api=api, handle=handle,
            location=self.location(cursor), loops=ctx.loop_ids(),
            every=every_nth(stack + [cursor])))

    def _forwarded_package_constructor(self, cursor, ctx):
        """make_shared<C>(args) of a package class calls C's constructor.

        The constructor taking as many arguments, else the one with the
        fewest more (defaulted) parameters: what the arguments bind to,
        such as the node name a subclass of rclcpp::Node receives
        (``std::make_shared<Talker>("talker")``).
        """
        declaration = _made_class(cursor)
        if declaration is None or not self.in_package(declaration):
            return
        arguments = list(cursor.get_arguments())
        candidates = []
        for constructor in declaration.get_children():
            # a constructor template (`template <class NodeT> C(NodeT)`)
            if constructor.kind != CK.CONSTRUCTOR and not (
                    constructor.kind == CK.FUNCTION_TEMPLATE and
                    constructor.spelling == declaration.spelling):
                continue
            extra = sum(1 for p in constructor.get_children()
                        if p.kind == CK.PARM_DECL) - len(arguments)
            if extra >= 0:
                candidates.append((extra, len(candidates), constructor))
        if candidates:
            constructor = min(candidates)[2]
            self._add_call(ctx, constructor.get_usr(), cursor)
            self._bind_arguments(constructor.get_usr(), arguments,
                                 caller=ctx.function)

    def _forwarded_constructor(self, cursor):
        """make_shared<X>(args) reads like X's constructor.

        X is read from the type made (``shared_ptr<X>``), so that an alias
        (``using Sync = message_filters::Synchronizer<P>``) and a template
        argument of X do not hide it.
        """
        declaration = _made_class(cursor)
        if declaration is not None:
            class_name = qualified_name(declaration)
        else:
            class_name = explicit_template_type(cursor)
        if not class_name:
            return None, None
        class_name = re.sub(r'<.*', '', class_name).strip()
        class_name = re.sub(r'^(?:class|struct)\s+', '', class_name)
        short = class_name.split('::')[-1]
        name = f'{class_name}::{short}'
        return name, ros_api.lookup_call(name)

    # --- argument helpers --------------------------------------------------

    def topic(self, argument):
        """Return (topic as written, is it a literal)."""
        if argument is None:
            return None, False
        literals = []
        has_variable = False
        for current in [argument] + list(walk_preorder(argument)):
            if current.kind == CK.STRING_LITERAL:
                literals.append(current)
            elif current.kind in REF_KINDS and current.referenced is not None \
                    and current.referenced.kind in HANDLE_KINDS:
                has_variable = True
            elif current.kind == CK.CALL_EXPR and \
                    current.referenced is not None and \
                    current.referenced.kind in VALUE_FUNCTION_KINDS:
                # get_parameter("topic").as_string(): a value, not a name
                has_variable = True
        if len(literals) == 1 and not has_variable:
            text = literals[0].spelling
            return _unquote(text), True
        text = expression_text(argument)
        return (text or None), False

    def argument(self, arguments, position):
        by_type = {
            ros_api.FIRST_STRING: _is_string,
            ros_api.FIRST_CALLABLE: _is_callable_argument,
            ros_api.FIRST_DURATION: _is_duration,
        }.get(position)
        if by_type is not None:
            return next((a for a in arguments if by_type(a)), None)
        if isinstance(position, int) and position < len(arguments):
            argument = arguments[position]
            return argument if _is_written(argument) else None
        return None

    def _bind_arguments(self, callee, arguments, first_index=0,
                        caller=None):
        """Record what a call passes to a package function's parameters.

        Handles, and string literals (a node name passed to a base class).
        """
        for index, argument in enumerate(arguments, start=first_index):
            if caller is not None and _is_string(argument):
                value, literal = self.topic(argument)
                if literal:
                    self.facts.string_arguments.append(model.StringArgument(
                        caller=caller, callee=callee, index=index,
                        value=value))
                    continue
            handle = first_handle(argument)
            if handle is not None and self.in_package(handle):
                self.facts.bindings.append(model.ParamBinding(
                    callee=callee, index=index, handle=handle.get_usr()))

    def _bound_arguments(self, argument):
        """Handles bound by boost::bind / std::bind to the callback."""
        for current in [argument] + list(walk_preorder(
                argument, stop=frozenset({CK.LAMBDA_EXPR}))):
            if current.kind != CK.CALL_EXPR or current.referenced is None or \
                    qualified_name(current.referenced) not in BIND_FUNCTIONS:
                continue
            bound = list(current.get_arguments())
            if not bound:
                return
            target = first_function(bound[0])
            if target is None or not self.in_package(target):
                return
            rest = bound[1:]
            # a bound method's first argument is the object, not a parameter
            if target.kind == CK.CXX_METHOD and not target.is_static_method():
                rest = rest[1:]
            self._bind_arguments(target.get_usr(), rest)
            return

    def resolve_callback(self, argument):
        """Return (function id, declaration cursor) of a callback argument."""
        if argument is None:
            return None, None
        self._bound_arguments(argument)
        for current in [argument] + list(walk_preorder(
                argument, stop=frozenset({CK.LAMBDA_EXPR}))):
            if current.kind == CK.LAMBDA_EXPR:
                self._consumed.add(self.key(current))
                lid = self._lambda_id(current)
                self._registered.add(lid)
                return lid, current
            if current.kind not in REF_KINDS:
                continue
            ref = current.referenced
            if ref is None:
                continue
            if ref.kind in FUNCTION_KINDS and self.in_package(ref):
                self._consumed.add(self.key(current))
                self._registered.add(ref.get_usr())
                return ref.get_usr(), ref
            if ref.kind == CK.VAR_DECL:
                for child in ref.get_children():
                    if child.kind == CK.LAMBDA_EXPR:
                        lid = self._lambda_id(child)
                        self._registered.add(lid)
                        return lid, child
            if ref.kind in HANDLE_KINDS and _is_callable(ref):
                # resolved at the end of the walk: see _resolve_stored_callbacks
                return CALLABLE_PREFIX + ref.get_usr(), None
        return None, None

    def _callbacks(self, arguments, position):
        if position == ros_api.ALL_CALLABLES:
            candidates = [a for a in arguments if _is_callable_argument(a)]
        elif position == ros_api.FIRST_CALLBACK:
            candidates = arguments
        else:
            positions = position if isinstance(position, tuple) \
                else (position,)
            candidates = [self.argument(arguments, p) for p in positions]
        found = []
        for argument in candidates:
            callback, _ = self.resolve_callback(argument)
            if callback:
                found.append(callback)
        return found

    def _callback_msg_type(self, declaration):
        if declaration is None:
            return None
        for child in declaration.get_children():
            if child.kind == CK.PARM_DECL:
                return normalize_msg_type(child.type.spelling)
        return None

    def target(self, cursor, stack):
        """The variable/field a created object is stored in, or None."""
        start = cursor.extent.start.offset
        for parent in reversed(stack):
            if isinstance(parent, _MemberInit):
                return parent.member
            kind = parent.kind
            if kind == CK.VAR_DECL:
                return parent
            if kind in STATEMENT_KINDS:
                return None
            if kind == CK.CALL_EXPR:
                children = child_cursors(parent)
                if parent.spelling == 'operator=' and children:
                    return first_handle(children[0])
                obj = call_object(parent)
                if obj is not None and obj.extent.end.offset <= start:
                    # x.reset(new ...), v.push_back(nh.advertise(...))
                    return first_handle(obj)
            if kind == CK.BINARY_OPERATOR:
                children = child_cursors(parent)
                if children and _binary_operator(parent, children[0]) == '=':
                    return first_handle(children[0])
        return None

    def _namespace_of(self, call, api=None, arguments=()):
        """The NodeHandle a create call was made on: USR or marker.

        For an API that takes the NodeHandle as an argument
        (``message_filters::Subscriber(nh, topic, 1)``), that argument.
        """
        obj = call_object(call)
        if api is not None and api.nh_arg is not None and \
                api.nh_arg < len(arguments):
            obj = arguments[api.nh_arg]
        if obj is None:
            return None
        for current in [obj] + list(walk_preorder(obj)):
            if current.kind == CK.CALL_EXPR and current.referenced is not None:
                api = ros_api.lookup_call(qualified_name(current.referenced))
                if api is not None and api.role == ros_api.PRIVATE_HANDLE:
                    return '~'
                if api is not None and api.role == ros_api.PUBLIC_HANDLE:
                    return ''
        handle = first_handle(obj)
        return handle.get_usr() if handle is not None else None

    # --- roles (named after ros_api roles) ----------------------------------

    def _on_publisher(self, cursor, ctx, stack, api, name, arguments):
        if self._wrapped_publisher(cursor, stack, api, arguments):
            return
        typed, api, arguments = self._with_options(cursor, api, arguments)
        topic, literal = self.topic(self.argument(arguments, api.name_arg))
        if topic is None and name.endswith('::init'):
            return
        if topic is None and api.name_arg and len(arguments) <= api.name_arg:
            return  # a default constructor: the topic comes with init()
        msg_type = self._table_msg_type(api.msg_type) or \
            self._type_name(arguments, api) or \
            self._template_msg_type(typed, name)
        target = self.target(cursor, stack)
        for common in self._endpoints(cursor, ctx, api, name, arguments,
                                      topic, literal, msg_type, target):
            self.facts.publishers.append(model.PublisherFact(
                handle_name=target.spelling if target is not None else None,
                **common))
        self._note_concatenation(
            self.facts.publishers[-1:], literal,
            self.argument(arguments, api.name_arg))

    def _wrapped_publisher(self, cursor, stack, api, arguments):
        """``RealtimePublisher<M>(pub)`` publishes through `pub`.

        Returns whether the call is such a wrapper (then it makes no
        publisher of its own; its publish sites count for `pub`).
        """
        if api.wraps_arg is None:
            return False
        written = _written(arguments)
        wrapped = self.argument(arguments, api.wraps_arg)
        if len(written) != 1 or wrapped is None or _is_string(wrapped):
            return False
        target = self.target(cursor, stack)
        handle = first_handle(wrapped)
        if target is not None and handle is not None:
            self.facts.handle_aliases.append(model.HandleAlias(
                alias=target.get_usr(), handle=handle.get_usr(),
                location=self.location(cursor)))
        return True

    def _argument_msg_type(self, arguments, api):
        if api.msg_type_arg is None:
            return None
        argument = self.argument(arguments, api.msg_type_arg)
        return normalize_msg_type(argument.type.get_canonical().spelling) \
            if argument is not None else None

    def _type_name(self, arguments, api):
        """The message type a generic API names: "pkg/msg/Name"."""
        if api.type_name_arg is None:
            return None
        written, literal = self.topic(
            self.argument(arguments, api.type_name_arg))
        if not literal or not re.fullmatch(r'\w+/\w+/\w+', written or ''):
            return None
        return written.replace('/', '::')

    def _template_msg_type(self, cursor, name):
        """The message type from ``<M>`` at the call or in the class."""
        return normalize_msg_type(
            explicit_template_type(cursor) or
            first_template_argument(self._object_type(cursor, name)))

    def _endpoints(self, cursor, ctx, api, name, arguments, topic, literal,
                   msg_type, target):
        """The fields shared by publisher and subscriber facts, per topic.

        image_transport's camera APIs also make `<dirname>/camera_info`.
        """
        topics = [(topic, msg_type)]
        if api.camera:
            topics.append((_camera_info(topic),
                           self._table_msg_type(ros_api.CAMERA_INFO_MSG)))
        topic_handle, affixes = self._topic_handle(arguments, api, literal)
        for each_topic, each_type in topics:
            yield dict(
                topic_handle=topic_handle, topic_affixes=affixes,
                function=ctx.function, api=ros_api.api_label(name),
                topic=each_topic, topic_is_literal=literal,
                msg_type=each_type,
                handle=target.get_usr() if target is not None else None,
                location=self.location(cursor),
                nh=self._namespace_of(cursor, api, arguments))

    def _object_type(self, cursor, name):
        """The class type a constructor or method belongs to.

        Canonical, so that aliases (``using Image = ...``) name the real
        message; through a smart pointer, the class pointed to.
        """
        if name.split('::')[-1] == name.split('::')[-2]:
            type_ = cursor.type
        else:
            obj = call_object(cursor)
            if obj is None:
                return ''
            type_ = obj.type
        spelling = type_.get_canonical().spelling
        if _SMART_POINTER.match(spelling):
            spelling = first_template_argument(spelling) or spelling
        return spelling

    def _table_msg_type(self, msg_type):
        """A message type the API table spells the ROS 1 way, for this unit.

        ROS 2 spells ``sensor_msgs::Image`` as ``sensor_msgs::msg::Image``.
        """
        if not msg_type or not self._ros2 or '::msg::' in msg_type:
            return msg_type
        package, _, name = msg_type.partition('::')
        return f'{package}::msg::{name}'

    def _options_call(self, argument):
        """The create()/init() call that filled a ros::*Options object.

        ``nh.subscribe(ops)`` / ``nh.advertise(ops)`` take the topic, the
        message type and the callback from ``ops =
        ros::SubscribeOptions::create<M>(topic, queue, callback, ...)`` or
        from ``ops.init<M>(topic, queue, callback)`` in the same function.
        """
        if argument is None:
            return None
        options = re.sub(r'^const |\s*&$', '',
                         argument.type.get_canonical().spelling)
        if options not in _OPTIONS_TYPES:
            return None
        handle = first_handle(argument)
        if handle is None:
            return None
        fillers = {f'{options}::create', f'{options}::init'}
        found = None
        scopes = [handle] + ([handle.semantic_parent]
                             if handle.kind == CK.VAR_DECL else [])
        for scope in scopes:
            for node in walk_preorder(scope):
                if node.kind != CK.CALL_EXPR or node.referenced is None or \
                        qualified_name(node.referenced) not in fillers:
                    continue
                if scope is handle or same_cursor(
                        first_handle(call_object(node)), handle):
                    found = node  # the last one written wins
            if found is not None:
                return found
        return None

    def _with_options(self, cursor, api, arguments):
        """(call with the endpoint's arguments, api, arguments)."""
        options = self._options_call(self.argument(arguments, api.name_arg))
        if options is None:
            return cursor, api, arguments
        # create/init(topic, queue_size, callback, ...): a subscription's
        # callback is the third argument, an advertisement has none
        return options, dataclasses.replace(
            api, name_arg=0,
            callback_arg=2 if api.callback_arg is not None else None), \
            list(options.get_arguments())

    def _on_subscriber(self, cursor, ctx, stack, api, name, arguments):
        typed, api, arguments = self._with_options(cursor, api, arguments)
        topic, literal = self.topic(self.argument(arguments, api.name_arg))
        if topic is None:
            return  # a default-constructed message_filters::Subscriber
        callback, declaration = self.resolve_callback(
            self.argument(arguments, api.callback_arg)) \
            if api.callback_arg is not None else (None, None)
        if api.type_name_arg is not None:
            # generic: the callback takes serialized messages of any type
            msg_type = self._type_name(arguments, api)
        else:
            msg_type = self._table_msg_type(api.msg_type) or \
                self._template_msg_type(typed, name) or \
                self._argument_msg_type(arguments, api) or \
                self._callback_msg_type(declaration)
        target = self.target(cursor, stack)
        if target is None and api.callback_arg is None:
            target = first_handle(call_object(cursor))
        for common in self._endpoints(cursor, ctx, api, name, arguments,
                                      topic, literal, msg_type, target):
            self.facts.subscribers.append(model.SubscriberFact(
                callback=callback, **common))
        self._note_concatenation(
            self.facts.subscribers[-1:], literal,
            self.argument(arguments, api.name_arg))

    def _note_concatenation(self, facts, literal, argument):
        """Resolve later a topic built with `+` from literals and strings.

        ``ns + "/pose"``, ``std::string("~") + name``,
        ``ros::names::append(ns, "pose")``: when every string variable in
        it is set only to one literal (see _resolve_string_names).
        """
        if literal or not facts or argument is None:
            return
        parts = _string_parts(argument)
        if parts and any(kind == 'variable' for kind, _ in parts):
            self._concatenated.append((facts[0], parts))

    def _topic_handle(self, arguments, api, literal):
        """(handle, affixes): where a non-literal topic comes from.

        A variable, or a parameter: ``create_publisher<M>(get_parameter(
        "topic").as_string(), 10)`` reads the parameter in place, recorded
        as ``param:<name>``. A variable joined with literals (``topic +
        "_filtered"``) gives [prefix, suffix] too, so that the value a
        launch file gives the parameter read into it makes the name.
        """
        if literal:
            return None, None
        argument = self.argument(arguments, api.name_arg)
        if argument is None:
            return None, None
        for current in [argument] + list(walk_preorder(argument)):
            if current.kind != CK.CALL_EXPR or current.referenced is None:
                continue
            read = ros_api.lookup_call(qualified_name(current.referenced))
            if read is not None and read.role == ros_api.PARAM_READ:
                param, is_literal = self.topic(
                    self.argument(list(current.get_arguments()), 0))
                if is_literal:
                    return 'param:' + param, None
        parts = _string_parts(argument)
        if parts is not None and len(parts) > 1:
            # `ns + "/pose"` is not the value of `ns` alone
            variables = [i for i, (kind, _) in enumerate(parts)
                         if kind == 'variable']
            if len(variables) != 1:
                return None, None
            index = variables[0]
            return parts[index][1], [
                ''.join(text for _, text in parts[:index]),
                ''.join(text for _, text in parts[index + 1:])]
        handle = first_handle(argument)
        return (handle.get_usr() if handle is not None else None), None

    def _on_param_read(self, cursor, ctx, stack, api, name, arguments):
        param, literal = self.topic(self.argument(arguments, 0))
        if not literal:
            return
        written = _written(arguments)
        if api.returns_value or len(written) == 1 or (
                name.endswith('::param') and len(written) == 2):
            # value = nh.param("name", default);
            # value = node->declare_parameter("name", default);
            # value = node->get_parameter("name").as_string()
            target = self.target(cursor, stack)
            default_argument = written[1] if len(written) > 1 else None
        else:
            # nh.param("name", variable, default) / getParam("name", var)
            target = first_handle(written[1]) if len(written) > 1 else None
            default_argument = written[2] if len(written) > 2 else None
        default = None
        if default_argument is not None:
            default, is_literal = self.topic(default_argument)
            default = default if is_literal else None
        self.facts.param_reads.append(model.ParamRead(
            function=ctx.function, name=param, default=default,
            handle=target.get_usr() if target is not None else None,
            nh='~' if api.node_private else self._namespace_of(cursor),
            location=self.location(cursor)))

    def _on_node_name(self, cursor, ctx, stack, api, name, arguments):
        node_name, literal = self.topic(
            self.argument(arguments, api.name_arg))
        namespace = None
        argument = self.argument(arguments, api.namespace_arg) \
            if api.namespace_arg is not None else None
        # Node("name", options) has no namespace argument
        if argument is not None and _is_string(argument):
            namespace, ns_literal = self.topic(argument)
            namespace = namespace if ns_literal else None
        name_param = None
        if not literal:
            # Base(const std::string & name) : Node(name): the name the
            # callers of Base pass
            handle = first_handle(self.argument(arguments, api.name_arg))
            if handle is not None and handle.kind == CK.PARM_DECL:
                name_param = handle.get_usr()
        self.facts.node_names.append(model.NodeNameFact(
            function=ctx.function, name=node_name if literal else None,
            namespace=namespace, location=self.location(cursor),
            name_param=name_param))

    def _on_timed_publisher(self, cursor, ctx, stack, api, name, arguments):
        """An object publishing from a timer of its own (ROS 2 Updater).

        Recorded as what it does: a timer whose callback (a function made
        up for it, at the construction) publishes through the object.
        """
        if not self._ros2:
            return  # the ROS 1 Updater publishes only when told to
        target = self.target(cursor, stack)
        if target is None:
            return
        location = self.location(cursor)
        # what the real timer calls; the id is unique per object
        callback = f'{api.label}::update@{location}'
        self.facts.functions.append(model.Function(
            id=callback, name=f'{api.label}::update', location=location))
        period = self.argument(arguments, api.period_arg)
        seconds = evaluate_number(period) if period is not None \
            else api.default_period
        rate_hz = _round(1.0 / seconds) if seconds else None
        self.facts.timers.append(model.TimerFact(
            function=ctx.function, api=api.label, callback=callback,
            period=expression_text(period) if period is not None
            else str(api.default_period),
            rate_hz=rate_hz, location=location))
        self.facts.publish_sites.append(model.PublishSite(
            function=callback, api=api.label, handle=target.get_usr(),
            location=location))

    def _on_client(self, cursor, ctx, stack, api, name, arguments):
        service, _ = self.topic(self.argument(arguments, api.name_arg))
        self.facts.clients.append(model.ClientFact(
            function=ctx.function, api=name, name=service,
            location=self.location(cursor)))

    def _on_timer(self, cursor, ctx, stack, api, name, arguments):
        callback, _ = self.resolve_callback(
            self.argument(arguments, api.callback_arg))
        period = self.argument(arguments, api.period_arg)
        self.facts.timers.append(model.TimerFact(
            function=ctx.function, api=ros_api.api_label(name),
            callback=callback,
            period=expression_text(period) if period is not None else '',
            rate_hz=_period_rate_hz(period),
            location=self.location(cursor)))

    def _on_service(self, cursor, ctx, stack, api, name, arguments):
        argument = self.argument(arguments, api.name_arg)
        service, literal = self.topic(argument)
        callback, _ = self.resolve_callback(
            self.argument(arguments, api.callback_arg))
        fact = model.ServiceFact(
            function=ctx.function, api=name, name=service,
            callback=callback, location=self.location(cursor))
        self.facts.services.append(fact)
        handle = first_handle(argument) if not literal else None
        if handle is not None:
            self._named_by_variable.append((fact, handle.get_usr()))

    def _on_action_server(self, cursor, ctx, stack, api, name, arguments):
        self._action(cursor, ctx, stack, api, name, arguments, 'server')

    def _on_action_client(self, cursor, ctx, stack, api, name, arguments):
        self._action(cursor, ctx, stack, api, name, arguments, 'client')

    def _action(self, cursor, ctx, stack, api, name, arguments, role):
        action, _ = self.topic(self.argument(arguments, api.name_arg)) \
            if api.name_arg is not None else (None, False)
        callbacks = self._callbacks(arguments, api.callback_arg) \
            if api.callback_arg is not None else []
        is_registration = api.name_arg is None
        target = first_handle(call_object(cursor)) if is_registration \
            else self.target(cursor, stack)
        self.facts.actions.append(model.ActionFact(
            function=ctx.function, api=ros_api.api_label(name), role=role,
            name=action, callbacks=callbacks,
            handle=target.get_usr() if target is not None else None,
            location=self.location(cursor) if not is_registration
            else 'registration:' + self.location(cursor)))

    def _on_publish(self, cursor, ctx, stack, api, name, arguments):
        handle = first_handle(call_object(cursor))
        self._publish_site(ctx, stack, cursor, name,
                           handle.get_usr() if handle is not None else None)

    def _on_rate(self, cursor, ctx, stack, api, name, arguments):
        target = self.target(cursor, stack)
        if target is None:
            return  # a temporary Rate paces nothing
        argument = self.argument(arguments, api.period_arg)
        rate_hz = None
        if argument is not None:
            if is_chrono_duration(argument.type):
                rate_hz = _period_rate_hz(argument)
            elif 'Duration' in argument.type.spelling:
                rate_hz = _period_rate_hz(argument)
            else:
                rate_hz = evaluate_number(argument)
        self.facts.rates.append(model.RateObject(
            handle=target.get_usr(), rate_hz=rate_hz,
            expression=expression_text(argument) if argument else '',
            location=self.location(cursor)))

    def paced_loop(self, ctx, sleep, clock):
        """(loop id, loop cursor) a sleep on `clock` paces, or None.

        It paces its innermost loop when it runs on every iteration and
        its clock (a Rate, a deadline) outlives the iteration.
        """
        if clock is None or not ctx.loops:
            return None
        loop_id, conditional_at_entry, loop = ctx.loops[-1]
        if ctx.conditional != conditional_at_entry:
            return None  # a sleep that may be skipped does not pace
        if _continue_before(loop, sleep):
            return None  # an iteration may end before the sleep
        declared = clock.extent.start
        if declared.file is not None and loop.extent.start.file is not None \
                and declared.file.name == loop.extent.start.file.name and \
                loop.extent.start.offset <= declared.offset \
                <= loop.extent.end.offset:
            return None  # a clock made anew in every iteration never adapts
        return loop_id, loop

    def _on_rate_sleep(self, cursor, ctx, stack, api, name, arguments):
        handle = first_handle(call_object(cursor))
        paced = self.paced_loop(ctx, cursor, handle)
        if paced is None:
            return
        loop_id, loop = paced
        self.facts.paced_loops.append(model.PacedLoop(
            loop=loop_id, function=ctx.function,
            rate_handle=handle.get_usr(), location=self.location(loop),
            sleep_location=self.location(cursor)))

    def _on_sync(self, cursor, ctx, stack, api, name, arguments):
        inputs = []
        for argument in arguments:
            handle = first_handle(argument)
            if handle is not None:
                inputs.append(handle.get_usr())
        if name.endswith('::connectInput'):
            target = first_handle(call_object(cursor))
        else:
            target = self.target(cursor, stack)
        self.facts.syncs.append(model.SyncFact(
            handle=target.get_usr() if target is not None else None,
            inputs=inputs, location=self.location(cursor)))

    def _on_register_callback(self, cursor, ctx, stack, api, name,
                              arguments):
        callback, _ = self.resolve_callback(
            self.argument(arguments, api.callback_arg))
        handle = first_handle(call_object(cursor))
        self.facts.registrations.append(model.Registration(
            function=ctx.function,
            handle=handle.get_usr() if handle is not None else None,
            callback=callback, location=self.location(cursor)))

    def _on_node_handle(self, cursor, ctx, stack, api, name, arguments):
        target = self.target(cursor, stack)
        if target is None:
            return
        namespace = ''
        written = _written(arguments)
        named = written and _is_string(written[0])
        parent = first_handle(written[0]) if written and not named else None
        if parent is not None:
            namespace = 'ref:' + parent.get_usr()
            if len(written) > 1:
                # NodeHandle(parent, "arm"); a sub-namespace not known
                # is marked so
                sub, literal = self.topic(written[1])
                namespace += '|' + (
                    sub if literal else UNKNOWN_NAMESPACE + (sub or '?'))
        elif named:
            # ros::NodeHandle nh("arm") / nh(real_name): a string variable
            # set once is its literal (see _resolve_string_names); a name
            # not known is marked so, never taken for the node's namespace
            namespace, literal = self.topic(written[0])
            if not literal:
                variable = first_handle(written[0])
                namespace = UNKNOWN_NAMESPACE + (namespace or '?')
                if variable is not None:
                    fact = model.NodeHandleFact(
                        handle=target.get_usr(), namespace=namespace)
                    self._namespaced_by_variable.append(
                        (fact, variable.get_usr()))
                    self.facts.node_handles.append(fact)
                    return
        # (ImageTransport(shared_from_this()): a node, not a namespace)
        self.facts.node_handles.append(model.NodeHandleFact(
            handle=target.get_usr(), namespace=namespace or ''))

    def _on_sub_node(self, cursor, ctx, stack, api, name, arguments):
        """``node->create_sub_node("arm")``: a handle in a sub-namespace."""
        target = self.target(cursor, stack)
        sub, literal = self.topic(self.argument(arguments, api.name_arg))
        if target is None or not literal:
            return
        parent = self._namespace_of(cursor)
        self.facts.node_handles.append(model.NodeHandleFact(
            handle=target.get_usr(),
            namespace=f'ref:{parent}|{sub}' if parent else sub))

    def _on_private_handle(self, cursor, ctx, stack, api, name, arguments):
        target = self.target(cursor, stack)
        if target is not None:
            self.facts.node_handles.append(model.NodeHandleFact(
                handle=target.get_usr(), namespace='~'))

    def _on_public_handle(self, cursor, ctx, stack, api, name, arguments):
        target = self.target(cursor, stack)
        if target is not None:
            self.facts.node_handles.append(model.NodeHandleFact(
                handle=target.get_usr(), namespace=''))


class _Context:
    """Where the walk is inside one function body."""

    def __init__(self, function, owner=None):
        self.function = function
        # the class of a method (a lambda's: its enclosing method's)
        self.owner = owner
        # (loop id, conditional depth at the loop, loop cursor)
        self.loops = []
        self.conditional = 0

    def loop_ids(self):
        return [loop_id for loop_id, _, _ in self.loops]


# what a string expression may pass through on its way to a literal or a
# variable: conversions, parentheses, std::string(...) temporaries
_STRING_WRAPPERS = frozenset({
    CK.UNEXPOSED_EXPR, CK.PAREN_EXPR, CK.CXX_FUNCTIONAL_CAST_EXPR,
    CK.CALL_EXPR, CK.CSTYLE_CAST_EXPR})
_NAMES_APPEND = 'ros::names::append'


def _string_parts(expression, depth=0):
    """[('literal', text) | ('variable', usr)] a string is joined from.

    None when it holds anything else (a call, a parameter read).
    """
    if expression is None or depth > 32:
        return None
    kind = expression.kind
    if kind == CK.STRING_LITERAL:
        return [('literal', _unquote(expression.spelling))]
    if kind in REF_KINDS and expression.referenced is not None and \
            expression.referenced.kind in HANDLE_KINDS:
        return [('variable', expression.referenced.get_usr())] \
            if _is_string(expression) else None
    if kind == CK.CALL_EXPR:
        name = qualified_name(expression.referenced) \
            if expression.referenced is not None else ''
        arguments = list(expression.get_arguments())
        if expression.spelling == 'operator+' and len(arguments) == 2:
            left, right = (_string_parts(a, depth + 1) for a in arguments)
            return left + right if left and right else None
        if name == _NAMES_APPEND and len(arguments) == 2:
            left, right = (_string_parts(a, depth + 1) for a in arguments)
            return left + [('literal', '/')] + right \
                if left and right else None
        if expression.spelling == 'basic_string' and arguments:
            # std::string(text): the constructor (its allocator defaulted)
            return _string_parts(arguments[0], depth + 1)
    children = [c for c in child_cursors(expression) if c.kind not in (
        CK.NAMESPACE_REF, CK.TYPE_REF, CK.TEMPLATE_REF)]
    if kind in _STRING_WRAPPERS and len(children) == 1:
        return _string_parts(children[0], depth + 1)
    return None


def _unquote(literal):
    match = re.match(r'^(?:u8|u|U|L)?"(.*)"$', literal, re.DOTALL)
    return match.group(1) if match else literal


CALLABLE_PREFIX = 'callable:'
_CALLABLE_TYPE = re.compile(r'\b(?:std|boost)::(?:function<|_Bind<)')


def _is_callable(cursor):
    """A variable/field holding a callable: std::function, bind results."""
    return bool(_CALLABLE_TYPE.search(cursor.type.get_canonical().spelling))


_CALLABLE_ARGUMENT = re.compile(
    r'\(lambda at |std::_Bind|std::function<|boost::_bi::bind_t|'
    r'\(\*\)\(|::\*\)\(')


def _is_callable_argument(argument):
    """A lambda, bind result, std::function or function (pointer)."""
    kind = argument.type.get_canonical().kind
    if kind in (ci.TypeKind.FUNCTIONPROTO, ci.TypeKind.MEMBERPOINTER):
        return True
    return bool(_CALLABLE_ARGUMENT.search(
        argument.type.get_canonical().spelling))


def _is_duration(argument):
    return is_chrono_duration(argument.type) or \
        'rclcpp::Duration' in argument.type.get_canonical().spelling


def _is_written(argument):
    """Whether an argument is written at the call (a default has no tokens)."""
    return next(iter(argument.get_tokens()), None) is not None


def _written(arguments):
    return [a for a in arguments if _is_written(a)]


def _is_string(argument):
    spelling = argument.type.get_canonical().spelling
    return 'basic_string' in spelling or 'char' in spelling


def _initializer(variable):
    """The expression a variable or field is initialised with, or None."""
    init = [c for c in variable.get_children()
            if c.kind not in (CK.TYPE_REF, CK.NAMESPACE_REF, CK.TEMPLATE_REF)]
    return init[0] if len(init) == 1 else None


def _camera_info(topic):
    if topic is None:
        return None
    head, _, _ = topic.rpartition('/')
    return f'{head}/camera_info' if head else 'camera_info'


def _is_logical(cursor, operands):
    """Whether a binary operator is ``||`` or ``&&`` (short-circuiting)."""
    if len(operands) != 2:
        return False
    # only the tokens between the operands: the operator
    between = ci.SourceRange.from_locations(
        operands[0].extent.end, operands[1].extent.start)
    return any(t.spelling in ('||', '&&', 'or', 'and')
               for t in cursor.translation_unit.get_tokens(extent=between))


def _continue_before(loop, sleep):
    """Whether a `continue` of this loop comes before the sleep call."""
    file = sleep.extent.start.file
    where = sleep.extent.start.offset
    todo = child_cursors(loop)
    while todo:
        current = todo.pop()
        if current.kind == CK.CONTINUE_STMT and \
                current.extent.start.file is not None and file is not None \
                and current.extent.start.file.name == file.name and \
                current.extent.start.offset < where:
            return True
        if current.kind in LOOP_KINDS or current.kind == CK.LAMBDA_EXPR:
            continue  # an inner loop's continue is its own
        todo.extend(child_cursors(current))
    return False


def _binary_operator(cursor, left):
    end = left.extent.end.offset
    for token in cursor.get_tokens():
        if token.extent.start.offset >= end:
            return token.spelling
    return None


_PERIOD_CLASSES = ('Duration', 'WallDuration')
_RATE_CLASSES = ('Rate', 'WallRate')


def _period_rate_hz(argument):
    """Hz of a period argument (``ros::Duration(0.1)``, ``Rate(10)``, 5.0)."""
    if argument is None:
        return None
    seconds = evaluate_duration_seconds(argument)
    if seconds:
        return _round(1.0 / seconds)
    for current in [argument] + list(walk_preorder(argument)):
        if current.kind == CK.CALL_EXPR and current.referenced is not None \
                and qualified_name(current.referenced) == \
                'rclcpp::Duration::from_seconds':
            values = [evaluate_number(a) for a in current.get_arguments()]
            return _round(1.0 / values[0]) if values and values[0] else None
        if current.kind != CK.CALL_EXPR or current.referenced is None or \
                current.referenced.kind != CK.CONSTRUCTOR:
            continue
        class_name = current.referenced.spelling
        arguments = list(current.get_arguments())
        values = [evaluate_number(a) for a in arguments]
        if class_name in _PERIOD_CLASSES:
            if len(values) == 1 and values[0]:
                return _round(1.0 / values[0])
            if len(arguments) == 1 and is_chrono_duration(arguments[0].type):
                # rclcpp::Duration from std::chrono::milliseconds(50)
                seconds = evaluate_duration_seconds(arguments[0])
                return _round(1.0 / seconds) if seconds else None
            if len(values) == 2 and None not in values:
                seconds = values[0] + values[1] * 1e-9
                return _round(1.0 / seconds) if seconds else None
            return None
        if class_name in _RATE_CLASSES and len(values) == 1:
            return _round(values[0]) if values[0] else None
    return None


def _round(value):
    # 1/0.1 is 9.999999999999998: keep the rate a person would write
    return round(value, 6) if value is not None else None
