# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The walk of a translation unit: where it is and what code refers to.

Only cursors whose file lies inside the package are walked (a TU with the
real ROS headers has ~400k cursors; the package's own code a few thousand).
The walker visits the package's declarations and function bodies, keeping
the function, loops and conditions it is in (a recorder's
:class:`~colcon_rsia.frontend.recorder.Context`); it records
functions, calls between them, references, lambdas and the callbacks they
are registered as. A ROS call is recognised by the qualified name of the
declaration it calls, looked up in :mod:`colcon_rsia.frontend.ros_api`,
and handed to the handler of its role (:mod:`.roles`, :mod:`.clocks`);
calls of the workspace's wrappers go to :mod:`.wrappers`. The helpers get
what they use, never the walker: the unit's facts, the
:class:`~.questions.Places` of the walk, the callback resolution of
:mod:`.callbacks`; a name argument as written, the variable a created
object is stored in, are answered from the cursors alone
(:mod:`.questions`, :mod:`.strings`, :mod:`.cursors`).
"""

import re

import clang.cindex as ci
from colcon_rsia.frontend import fact_builder
from colcon_rsia.frontend import recorder
from colcon_rsia.frontend import ros_api
from colcon_rsia.frontend.cpp import clocks
from colcon_rsia.frontend.cpp import questions
from colcon_rsia.frontend.cpp import roles
from colcon_rsia.frontend.cpp import strings
from colcon_rsia.frontend.cpp import token_facts
from colcon_rsia.frontend.cpp import wrappers
from colcon_rsia.frontend.cpp.callbacks import Callbacks
from colcon_rsia.frontend.cpp.callbacks import is_callable
from colcon_rsia.frontend.cpp.const_eval import source_tokens
from colcon_rsia.frontend.cpp.cursors import aliased_class
from colcon_rsia.frontend.cpp.cursors import base_class_names
from colcon_rsia.frontend.cpp.cursors import call_arguments
from colcon_rsia.frontend.cpp.cursors import call_object
from colcon_rsia.frontend.cpp.cursors import child_cursors
from colcon_rsia.frontend.cpp.cursors import CLASS_KINDS
from colcon_rsia.frontend.cpp.cursors import declared_by_catch_all
from colcon_rsia.frontend.cpp.cursors import explicit_template_type
from colcon_rsia.frontend.cpp.cursors import first_handle
from colcon_rsia.frontend.cpp.cursors import FUNCTION_KINDS
from colcon_rsia.frontend.cpp.cursors import holder_of_member
from colcon_rsia.frontend.cpp.cursors import holds_node_handle
from colcon_rsia.frontend.cpp.cursors import initializer
from colcon_rsia.frontend.cpp.cursors import is_logical
from colcon_rsia.frontend.cpp.cursors import is_node_handle
from colcon_rsia.frontend.cpp.cursors import LOOP_KINDS
from colcon_rsia.frontend.cpp.cursors import made_class
from colcon_rsia.frontend.cpp.cursors import overload_candidate
from colcon_rsia.frontend.cpp.cursors import plain_handle
from colcon_rsia.frontend.cpp.cursors import qualified_name
from colcon_rsia.frontend.cpp.cursors import REF_KINDS
from colcon_rsia.frontend.cpp.cursors import repaired_call_name
from colcon_rsia.frontend.cpp.cursors import REPAIRED_CONSTRUCTOR
from colcon_rsia.frontend.cpp.cursors import REPAIRED_PREFIX
from colcon_rsia.frontend.cpp.cursors import same_cursor
from colcon_rsia.frontend.cpp.cursors import SCOPE_KINDS
from colcon_rsia.frontend.cpp.cursors import template_member
from colcon_rsia.frontend.cpp.cursors import walk_preorder
from colcon_rsia.frontend.cpp.parse import MAX_DIAGNOSTICS_PER_TU
from colcon_rsia.frontend.cpp.plugin_exports import plugin_exports
from colcon_rsia.frontend.cpp.questions import dependent_call_name
from colcon_rsia.frontend.cpp.questions import MemberInit
from colcon_rsia.frontend.facts import RETURNED_HANDLE
from colcon_rsia.summary.kinds import UNKNOWN_NAMESPACE

CK = ci.CursorKind


def _qualified_call(call, callee):
    """Whether a call names its callee qualified (``Base::f()``)."""
    tokens = [t.spelling for t in source_tokens(call)]
    for i in range(1, len(tokens) - 1):
        if tokens[i] == callee.spelling and tokens[i + 1] in ('(', '<'):
            return tokens[i - 1] == '::'
    return False


def _on_this(call):
    """Whether a member call is made on the object itself (`this`)."""
    obj = call_object(call)
    while obj is not None and obj.kind == CK.UNEXPOSED_EXPR and \
            len(child_cursors(obj)) == 1:
        obj = child_cursors(obj)[0]
    return obj is None or obj.kind == CK.CXX_THIS_EXPR


def extract_facts(tu, *, package_path, source, external_wrappers=None):
    """Walk the package's own code in a parsed TU and return its facts.

    :param tu: the parsed translation unit
    :param str package_path: absolute path of the package source
    :param str source: the TU's main file, relative to the package
    :param external_wrappers: the wrappers.ExternalWrappers of the
      workspace's other packages, for calls of functions with no body here
    :rtype: colcon_rsia.frontend.facts.TuFacts
    """
    walker = _Walker(package_path, fact_builder.unit_facts(source),
                     external_wrappers=external_wrappers)
    walker.walk(tu)
    walker.facts.diagnostics = walker.problems + walker.facts.diagnostics
    return walker.facts


class _Walker:
    """Collects the facts of one TU; see :func:`extract_facts`."""

    def __init__(self, package_path, facts, external_wrappers=None):
        self.facts = facts
        # where cursors are, the unit's ROS version: what every helper asks
        self.places = questions.Places(package_path)
        self._lambdas_in_variables = set()
        # what string variables hold, resolved at the end of the walk
        self.string_variables = strings.StringVariables(
            facts, self.places.in_package)
        # the callbacks arguments name, what calls bind to parameters
        self.callbacks = Callbacks(facts, self.places, self.string_variables)
        resolve_callback = self.callbacks.resolve_callback
        # declarations whose walk failed: one line each, the rest goes on
        self.problems = []
        # the workspace's wrapper functions this unit calls
        self._wrappers = wrappers.Summaries(
            facts, self.places, resolve_callback=resolve_callback,
            problems=self.problems, external=external_wrappers)
        # {function id: definition} of the package's functions walked
        self._definitions = {}
        # {class name: [definition]} of the package's classes
        self._classes = {}
        # {file: {end offset: start offset}}: the calls the AST resolved,
        # which the tokens of their place then leave alone (a call is known
        # by where its `)` ends: its callee's spelling may be an operator's)
        self._resolved_calls = {}
        # Qt and boost::asio timers, sleep_until loops
        self._clocks = clocks.OtherClocks(
            facts, self.places, resolve_callback=resolve_callback)
        # what each role of ros_api does to the facts
        self._handlers = {
            **roles.RosRoles(
                facts, self.places, resolve_callback=resolve_callback,
                string_variables=self.string_variables,
                stored_then_registered=(
                    self.callbacks.stored_then_registered)).handlers(),
            **self._clocks.handlers(),
        }

    def _note_resolved(self, cursor):
        """Remember a call the AST resolved (see token_facts)."""
        start, end = cursor.extent.start, cursor.extent.end
        if start.file is not None:
            ends = self._resolved_calls.setdefault(start.file.name, {})
            ends[end.offset] = min(start.offset, ends.get(end.offset, start.offset))

    # --- declarations ------------------------------------------------------

    def walk(self, tu):
        self.facts.plugin_exports.extend(plugin_exports(tu.spelling))
        # a ROS 2 unit: some APIs (diagnostic_updater) keep their ROS 1
        # names but behave differently
        self.places.ros2 = any(
            c.kind == CK.NAMESPACE and c.spelling == 'rclcpp'
            for c in tu.cursor.get_children())
        for cursor in tu.cursor.get_children():
            if self.places.in_package(cursor):
                self._declaration(cursor)
        # what the AST lost of the bodies walked, from their tokens
        token_facts.recover_facts(
            tu, self.facts, definitions=self._definitions,
            classes=self._classes, relpath=self.places.relative_path,
            ros2=self.places.ros2, resolved_calls=self._resolved_calls)
        if len(self.problems) > MAX_DIAGNOSTICS_PER_TU:
            lost = len(self.problems) - MAX_DIAGNOSTICS_PER_TU
            del self.problems[MAX_DIAGNOSTICS_PER_TU:]
            self.problems.append(f'... and {lost} more declarations skipped')
        # a lambda stored in a variable and then registered as a callback
        # is a root, not something its defining function calls
        self.facts.calls = [
            c for c in self.facts.calls
            if not (c.kind == 'ref' and c.callee in self.callbacks.registered and
                    (c.callee in self._lambdas_in_variables or
                     c.callee in self.callbacks.stored_then_registered))]
        self._clocks.finish()
        self.callbacks.resolve_stored_callbacks()
        self.string_variables.resolve()
        self.facts.wrappers = self._wrappers.exported(self._definitions)
        # cursors keep their unit's AST alive: not past the walk
        self._definitions.clear()
        self._classes.clear()

    def _declaration(self, cursor):
        try:
            kind = cursor.kind
        except ValueError:
            return  # a cursor kind this libclang binding does not know
        if kind in SCOPE_KINDS:
            if kind in CLASS_KINDS:
                if cursor.is_definition():
                    # (for the constructors the tokens name by class)
                    self._classes.setdefault(cursor.spelling, []).append(
                        cursor)
                # what a plugin class inherits its methods from
                name = qualified_name(cursor)
                self.facts.class_bases.extend(
                    [name, base] for base in base_class_names(cursor)
                    if [name, base] not in self.facts.class_bases)
            for child in cursor.get_children():
                if self.places.in_package(child):
                    self._declaration(child)
            return
        if kind in (CK.TYPEDEF_DECL, CK.TYPE_ALIAS_DECL):
            declaration = aliased_class(cursor)
            if declaration is not None:
                self.facts.class_aliases.append(
                    [qualified_name(cursor), qualified_name(declaration)])
            return
        # what invalid code leaves in the AST may surprise any rule below:
        # such a declaration loses its own facts, never the unit's
        try:
            if kind in FUNCTION_KINDS:
                if cursor.is_definition():
                    self._function(cursor)
            elif kind in (CK.FIELD_DECL, CK.VAR_DECL):
                self._declared_object(cursor, function=None)
                if kind == CK.FIELD_DECL:
                    self._member_initializer(cursor)
                else:
                    self._initialized_string(cursor)
        except Exception as e:  # noqa: B902
            self.problems.append(
                f'{self.places.location(cursor)}: {cursor.spelling or kind.name} '
                f'not analysed (internal error: {type(e).__name__}: {e}); '
                'please report it')

    def _class_id(self, cursor):
        parent = cursor.semantic_parent
        if parent is not None and parent.kind in CLASS_KINDS:
            return parent.get_usr()
        return None

    def _member_initializer(self, field):
        """``Poller<M> odom_{this, "odom"};``: what a constructor runs.

        A default member initializer runs in every constructor of the
        class that does not set the member itself; it is walked as part
        of the first constructor the class declares (none declared: no
        function of the package runs it).
        """
        init = initializer(field)
        if init is None:
            return
        owner = field.semantic_parent
        constructor = next(
            (c for c in owner.get_children() if c.kind == CK.CONSTRUCTOR),
            None) if owner is not None else None
        ctx = recorder.Context(constructor.get_usr(), owner=owner) \
            if constructor is not None else None
        self._initialize_member(field, init, ctx)

    def _initialize_member(self, member, expression, ctx):
        """A member set to an expression by the constructor `ctx` runs.

        Its init list, or the member's default initializer (`ctx` None:
        no constructor of the package runs it, only its string value is
        noted).
        """
        self.string_variables.assignment(member, expression)
        if ctx is None:
            return
        if is_callable(member):
            self.callbacks.store_callable(member, expression)
        self._visit(expression, ctx, [MemberInit(member)])

    def _function(self, cursor):
        fid = cursor.get_usr()
        self._definitions[fid] = cursor
        params = [c for c in cursor.get_children() if c.kind == CK.PARM_DECL]
        fact_builder.add_function(
            self.facts, id=fid, name=qualified_name(cursor),
            location=self.places.location(cursor),
            class_id=self._class_id(cursor),
            params=[c.get_usr() for c in params])
        for param in params:
            if is_node_handle(param):
                # a NodeHandle its callers give: their handle's namespace
                # when the node's calls show it (node_facts), else one the
                # analysis does not know, never the root's
                fact_builder.add_node_handle(
                    self.facts, handle=param.get_usr(),
                    namespace=f'{UNKNOWN_NAMESPACE}{param.spelling}')
        if holds_node_handle(cursor.result_type):
            self._returned_handles(cursor)
        parent = cursor.semantic_parent
        owner = parent if parent is not None and \
            parent.kind in CLASS_KINDS else None
        ctx = recorder.Context(fid, owner=owner)
        pending_member = None
        for child in cursor.get_children():
            if child.kind == CK.MEMBER_REF:
                pending_member = child.referenced
                continue
            if child.kind in (CK.PARM_DECL, CK.TYPE_REF, CK.NAMESPACE_REF,
                              CK.TEMPLATE_REF, CK.TEMPLATE_TYPE_PARAMETER,
                              CK.TEMPLATE_NON_TYPE_PARAMETER):
                continue
            if pending_member is not None:
                self._initialize_member(pending_member, child, ctx)
            else:
                self._visit(child, ctx, [])
            pending_member = None

    def _returned_handles(self, function):
        """``ros::NodeHandle& node() { return node_; }``: what it returns.

        A call of the function stands for the handle (cursors.handle_marker
        gives ``ret:<its USR>``): the member or variable it returns, or,
        when it returns anything else (a handle made there), one whose
        namespace the analysis does not know.
        """
        fid = RETURNED_HANDLE + function.get_usr()
        for current in walk_preorder(
                function, stop=frozenset({CK.LAMBDA_EXPR})):
            if current.kind != CK.RETURN_STMT:
                continue
            returned = next(current.get_children(), None)
            handle = plain_handle(returned)
            if handle is not None and self.places.in_package(handle):
                fact_builder.add_handle_alias(
                    self.facts, alias=fid, handle=handle.get_usr(),
                    location=self.places.location(current))
            else:
                fact_builder.add_node_handle(
                    self.facts, handle=fid,
                    namespace=f'{UNKNOWN_NAMESPACE}{function.spelling}()')

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
                    msg_type=self.places.table_msg_type(api.msg_type),
                    handle=cursor.get_usr(), location=self.places.location(cursor),
                    class_id=class_id)
                if api.role == ros_api.DECLARED_PUBLISHER:
                    fact_builder.add_publisher(
                        self.facts, handle_name=cursor.spelling, **common)
                else:
                    fact_builder.add_subscriber(
                        self.facts, callback=None, **common)
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
            init = initializer(cursor)
            if init is not None and init.kind == CK.LAMBDA_EXPR:
                self._lambdas_in_variables.add(self.places.lambda_id(init))
            elif init is not None and is_callable(cursor):
                self.callbacks.store_callable(cursor, init)
        children = child_cursors(cursor)
        stack.append(cursor)
        if kind in LOOP_KINDS:
            with ctx.loop(self.places.loop_id(cursor), cursor):
                for child in children:
                    self._visit(child, ctx, stack)
        elif children and (
                kind in (CK.IF_STMT, CK.SWITCH_STMT, CK.CONDITIONAL_OPERATOR,
                         CK.CXX_TRY_STMT) or
                kind == CK.BINARY_OPERATOR and is_logical(cursor, children)):
            # the condition (the try block, the left operand) runs every
            # time; the branches (the handlers, the right operand) may not
            self._visit(children[0], ctx, stack)
            with ctx.branch():
                for child in children[1:]:
                    self._visit(child, ctx, stack)
        else:
            for child in children:
                self._visit(child, ctx, stack)
        stack.pop()

    def _initialized_string(self, variable):
        init = initializer(variable)
        if init is not None:
            self.string_variables.assignment(variable, init)

    def _copied_handle(self, variable):
        """``auto pub = pub_;``: the local copy publishes through `pub_`.

        So do ``std::weak_ptr<P> weak = pub_;`` and ``auto p = weak.lock();``.
        """
        init = initializer(variable)
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
                self.places.in_package(handle):
            fact_builder.add_handle_alias(
                self.facts, alias=variable.get_usr(), handle=handle.get_usr(),
                location=self.places.location(variable))

    def _lambda(self, cursor, ctx):
        lid = self.places.lambda_id(cursor)
        fact_builder.add_function(
            self.facts, id=lid, name=f'lambda@{self.places.location(cursor)}',
            location=self.places.location(cursor),
            class_id=None,
            params=[c.get_usr() for c in cursor.get_children()
                    if c.kind == CK.PARM_DECL])
        if self.places.key(cursor) not in self.callbacks.consumed:
            self._add_call(ctx, lid, cursor, kind='ref')
        inner = recorder.Context(lid, owner=ctx.owner)
        for child in cursor.get_children():
            if child.kind == CK.COMPOUND_STMT:
                self._visit(child, inner, [])

    def _add_call(self, ctx, callee, cursor, kind='call', virtual=None,
                  name_arguments=(), on_this=False):
        fact_builder.add_call(
            self.facts, caller=ctx.function, callee=callee,
            location=self.places.location(cursor), loops=ctx.loop_ids(), kind=kind,
            virtual=virtual, on_this=on_this,
            name_arguments=list(name_arguments))

    def _reference(self, cursor, ctx, stack):
        """A function named but not called here: it may be called later."""
        ref = cursor.referenced
        if ref is None or ref.kind not in FUNCTION_KINDS or \
                not self.places.in_package(ref):
            return
        if self.places.key(cursor) in self.callbacks.consumed:
            return
        for parent in stack[-2:]:
            if getattr(parent, 'kind', None) == CK.CALL_EXPR and \
                    same_cursor(parent.referenced, ref):
                return  # the callee of a call, counted by _call
        self._add_call(ctx, template_member(ref).get_usr(), cursor,
                       kind='ref')

    def _call(self, cursor, ctx, stack):
        ref = cursor.referenced
        if ref is None:
            ref = overload_candidate(cursor)
        if ref is None:
            self._dependent_call(cursor, ctx, stack)
            return
        self._note_resolved(cursor)
        if cursor.spelling == 'operator=':
            children = child_cursors(cursor)
            target = first_handle(children[0]) if children else None
            if target is not None and is_callable(target):
                self.callbacks.store_callable(target, children[-1])
                if qualified_name(target) == \
                        ros_api.PUBLISHER_MATCHED_CALLBACK:
                    # kept with the options object too: the publisher made
                    # with it names it (roles._on_publisher)
                    holder = holder_of_member(children[0])
                    if holder is not None:
                        self.callbacks.store_callable(
                            holder, children[-1], consume=False)
            elif target is not None and len(children) > 1:
                self.string_variables.assignment(target, children[-1])
        name = qualified_name(ref)
        if ref.kind in FUNCTION_KINDS and self.places.in_package(ref) and \
                ros_api.lookup_call(name) is None:
            # (an API is the API wherever it is declared: in the package
            # that implements it, image_transport's own advertise() is one)
            self._package_call(ctx, ref, cursor, call_arguments(cursor))
            return
        if name.startswith(REPAIRED_PREFIX) or \
                ref.spelling == REPAIRED_CONSTRUCTOR:
            name = repaired_call_name(cursor, ref) or name
        api = ros_api.lookup_call(name)
        if api is None and (name.startswith(REPAIRED_PREFIX) or
                            declared_by_catch_all(ref)):
            # a member of the model's catch-all value (`rviz_node->
            # create_subscription<M>(...)` on what an unknown base class
            # holds), a function a repair declared (`create_publisher<M>(
            # "plan", 1)` in a class whose base is unknown): known by its
            # name alone, as in a template
            self._dependent_call(cursor, ctx, stack)
            return
        arguments = None
        if api is None and (name in ros_api.FORWARDING_FACTORIES or
                            _is_static_factory(ref)):
            self._forwarded_package_constructor(cursor, ctx)
            name, api = self._forwarded_constructor(cursor)
        if api is None:
            if ref.kind in FUNCTION_KINDS and \
                    self.places.is_workspace_declaration(ref):
                self._wrappers.record_call(cursor, ctx, stack, ref)
            return
        arguments = call_arguments(cursor)
        self._handlers[api.role](cursor, ctx, stack, api, name, arguments)

    def _dependent_call(self, cursor, ctx, stack):
        """``node->template create_publisher<M>(...)`` in a template.

        On an object of a template parameter's type (``NodeT node``) the
        call resolves only when the template is instantiated, which the
        AST does not show: the endpoint-creating methods are recognised by
        their name (see ros_api.METHODS_BY_NAME). So are they on a value
        whose type the model mode could not know (a catch-all).
        """
        name = dependent_call_name(cursor, ros2=self.places.ros2)
        if name is None or name == ros_api.QT_CONNECT and \
                not clocks.connects_timer(cursor):
            return
        self._note_resolved(cursor)
        api = ros_api.lookup_call(name)
        self._handlers[api.role](
            cursor, ctx, stack, api, name, call_arguments(cursor))

    def _forwarded_package_constructor(self, cursor, ctx):
        """make_shared<C>(args) of a package class calls C's constructor.

        The constructor taking as many arguments, else the one with the
        fewest more (defaulted) parameters: what the arguments bind to,
        such as the node name a subclass of rclcpp::Node receives
        (``std::make_shared<Talker>("talker")``).
        """
        declaration = made_class(cursor)
        if declaration is None or not self.places.in_package(declaration):
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
            self._package_call(ctx, min(candidates)[2], cursor, arguments)

    def _package_call(self, ctx, callee, cursor, arguments):
        """A call of the package's function (or constructor) `callee`."""
        callee = template_member(callee)
        # `Base::onInit()` calls that function: a qualified name never
        # dispatches to an override
        virtual = callee.kind == CK.CXX_METHOD and \
            callee.is_virtual_method() and not _qualified_call(cursor, callee)
        self._add_call(ctx, callee.get_usr(), cursor,
                       virtual=qualified_name(callee) if virtual else None,
                       on_this=virtual and _on_this(cursor),
                       name_arguments=strings.name_arguments(
                           callee, arguments, self.places.in_package))
        self.callbacks.bind_arguments(callee.get_usr(), arguments,
                                      caller=ctx.function)
        self.callbacks.bind_parameters(callee, arguments)

    def _forwarded_constructor(self, cursor):
        """make_shared<X>(args) reads like X's constructor.

        X is read from the type made (``shared_ptr<X>``), so that an alias
        (``using Sync = message_filters::Synchronizer<P>``) and a template
        argument of X do not hide it.
        """
        declaration = made_class(cursor)
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


def _is_static_factory(function):
    """``C::make_shared(args)``: a static member forwarding to C's constructor.

    (The smart-pointer definitions ROS 2 classes declare, and any class's
    own factory of that name.)
    """
    return function.kind == CK.CXX_METHOD and function.is_static_method() \
        and function.spelling in ros_api.FORWARDING_FACTORY_NAMES
