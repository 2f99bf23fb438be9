# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Questions about libclang cursors that the C++ front end asks.

Names, message types, children, the object of a member call, the handle
an expression starts from, what kind of value an argument is: shared by
the walk of a unit (:mod:`colcon_rsia.frontend.cpp.walker`), the handlers
of the API roles (:mod:`colcon_rsia.frontend.cpp.roles`) and the summaries
of the workspace's wrappers (:mod:`colcon_rsia.frontend.cpp.wrappers`).
"""

import itertools
import os
import re

import clang.cindex as ci
from colcon_rsia.frontend import ros_api
from colcon_rsia.frontend.cpp.const_eval import is_chrono_duration
from colcon_rsia.frontend.cpp.const_eval import source_tokens
from colcon_rsia.frontend.cpp.model_mode.stubs import CATCH_ALL_DIRS
from colcon_rsia.frontend.facts import RETURNED_HANDLE
from colcon_rsia.summary.kinds import UNKNOWN_NAMESPACE

CK = ci.CursorKind

FUNCTION_KINDS = frozenset({
    CK.FUNCTION_DECL, CK.CXX_METHOD, CK.CONSTRUCTOR, CK.DESTRUCTOR,
    CK.FUNCTION_TEMPLATE, CK.CONVERSION_FUNCTION,
})
CLASS_KINDS = frozenset({
    CK.CLASS_DECL, CK.STRUCT_DECL, CK.CLASS_TEMPLATE,
    CK.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION, CK.UNION_DECL,
})
SCOPE_KINDS = CLASS_KINDS | {CK.NAMESPACE, CK.LINKAGE_SPEC}
LOOP_KINDS = frozenset({
    CK.WHILE_STMT, CK.FOR_STMT, CK.DO_STMT, CK.CXX_FOR_RANGE_STMT})
HANDLE_KINDS = frozenset({CK.VAR_DECL, CK.FIELD_DECL, CK.PARM_DECL})
# calls computing a value (constructors and conversions only wrap one)
VALUE_FUNCTION_KINDS = frozenset({
    CK.FUNCTION_DECL, CK.CXX_METHOD, CK.FUNCTION_TEMPLATE})
REF_KINDS = frozenset({CK.DECL_REF_EXPR, CK.MEMBER_REF_EXPR})
# statements end the search for the variable a call's result is stored in
STATEMENT_KINDS = frozenset({
    CK.COMPOUND_STMT, CK.RETURN_STMT, CK.IF_STMT, CK.WHILE_STMT,
    CK.FOR_STMT, CK.DO_STMT, CK.SWITCH_STMT, CK.LAMBDA_EXPR,
    CK.CXX_FOR_RANGE_STMT,
})


def same_cursor(a, b):
    """Whether two cursors are the same; None is no cursor, never equal.

    libclang returns None (or a null cursor) for what invalid code leaves
    unresolved, and ``Cursor.__eq__`` raises on anything but a cursor.
    """
    return a is not None and b is not None and a == b


def qualified_name(cursor):
    """Return ``ns::Class::name`` of a declaration (no template args)."""
    parts = []
    while cursor is not None and cursor.kind != CK.TRANSLATION_UNIT:
        if cursor.spelling:
            parts.append(cursor.spelling)
        cursor = cursor.semantic_parent
    return '::'.join(reversed(parts))


_MSG_ALLOCATOR = re.compile(r'(\w+)_<\s*(?:class\s+)?std::allocator<void>\s*>')
_MSG_WRAPPER = re.compile(
    r'^(?:(?:boost|std)::(?:shared_ptr|unique_ptr)|ros::MessageEvent)'
    r'<(.*?)(?:,std::default_delete<.*>)?>$')


def normalize_msg_type(spelling):
    """``const std_msgs::String::ConstPtr &`` -> ``std_msgs::String``."""
    if not spelling:
        return None
    text = _MSG_ALLOCATOR.sub(r'\1', spelling)
    text = re.sub(r'\b(?:const|volatile|struct|class|typename)\b', '', text)
    text = text.replace('&', '').replace('*', '').strip()
    text = re.sub(r'\s+', ' ', text)
    for _ in range(3):
        match = _MSG_WRAPPER.match(text.replace(' ', ''))
        if not match:
            break
        text = match.group(1)
    text = text.replace(' ', '')
    # ROS 2 pointer aliases too: `M::SharedPtr`, `M::ConstSharedPtr`, ...
    text = re.sub(
        r'::(?:ConstPtr|Ptr|SharedPtr|ConstSharedPtr|UniquePtr|'
        r'ConstUniquePtr)$', '', text)
    return text or None


def first_template_argument(spelling):
    """``A`` of a type spelled ``X<A, B>``, or None."""
    start = spelling.find('<')
    if start < 0:
        return None
    depth = 0
    for i in range(start, len(spelling)):
        ch = spelling[i]
        if ch == '<':
            depth += 1
        elif ch == '>':
            depth -= 1
            if depth == 0:
                return spelling[start + 1:i]
        elif ch == ',' and depth == 1:
            return spelling[start + 1:i]
    return None


def child_cursors(cursor):
    """The children of a cursor, as a list."""
    return list(cursor.get_children())


def walk_preorder(cursor, stop=LOOP_KINDS - LOOP_KINDS):
    """Yield the cursors below `cursor` (not into `stop` kinds)."""
    todo = child_cursors(cursor)[::-1]
    while todo:
        current = todo.pop()
        yield current
        if current.kind not in stop:
            todo.extend(child_cursors(current)[::-1])


def _named_handles(cursor):
    """The variables/fields/parameters an expression names, in preorder.

    Not those inside a lambda it holds.
    """
    for current in itertools.chain([cursor], walk_preorder(
            cursor, stop=frozenset({CK.LAMBDA_EXPR}))):
        if current.kind in REF_KINDS:
            ref = current.referenced
            if ref is not None and ref.kind in HANDLE_KINDS:
                yield ref


def first_handle(cursor):
    """The variable/field/parameter an object expression starts from."""
    if cursor is None:
        return None
    return next(_named_handles(cursor), None)


def ranged_container(variable, stack):
    """The container a range-for loop's variable is an element of, or None.

    ``for (auto& pub : pubs_) pub.publish(m);`` publishes through the
    publishers ``pubs_`` holds. `stack` holds the cursors around the use.
    """
    if variable is None or variable.kind != CK.VAR_DECL:
        return None
    for parent in reversed(stack):
        if getattr(parent, 'kind', None) != CK.CXX_FOR_RANGE_STMT:
            continue
        children = list(parent.get_children())
        if len(children) > 1 and same_cursor(children[0], variable):
            return first_handle(children[1])
    return None


def holder_of_member(cursor):
    """The variable or field a member expression starts from.

    ``options.event_callbacks.matched_callback``: ``options``, the last
    one it names (:func:`first_handle` gives the member, the first).
    """
    holder = None
    for holder in _named_handles(cursor):
        pass
    return holder


def handle_marker(obj, foreign=None, own=None):
    """The NodeHandle an object expression is: USR or namespace marker.

    ``getPrivateNodeHandle()`` is '~', ``getNodeHandle()`` '' (the node's
    namespace), a variable its USR (its namespace is resolved later);
    None when the expression names no handle. A member or variable
    `foreign` says is set up by code the analysis does not read (another
    library's base class, a name only the model mode's repairs declare):
    a namespace not known, ``?<name>``. A function `own` says is the
    package's and that returns a handle (``link_->node()->advertise``):
    ``ret:<its USR>``, which stands for the handle it returns
    (walker._function).
    """
    if obj is None:
        return None
    for current in [obj] + list(walk_preorder(obj)):
        if current.kind == CK.CALL_EXPR and current.referenced is not None:
            api = ros_api.lookup_call(qualified_name(current.referenced))
            if api is not None and api.role == ros_api.PRIVATE_HANDLE:
                return '~'
            if api is not None and api.role == ros_api.PUBLIC_HANDLE:
                return ''
            if api is None and own is not None and \
                    holds_node_handle(current.referenced.result_type) and \
                    own(current.referenced):
                return RETURNED_HANDLE + current.referenced.get_usr()
    handle = first_handle(obj)
    if handle is not None and handle.kind in (CK.FIELD_DECL, CK.VAR_DECL) \
            and foreign is not None and foreign(handle):
        return UNKNOWN_NAMESPACE + handle.spelling
    return handle.get_usr() if handle is not None else None


# a ROS 1 NodeHandle (by value, reference or pointer): it carries a namespace
_NODE_HANDLE_TYPE = re.compile(r'^(?:const )?ros::NodeHandle(?: ?[&*]+)?$')


def is_node_handle(cursor):
    """Whether an expression or declaration is a ROS 1 NodeHandle."""
    return bool(_NODE_HANDLE_TYPE.match(cursor.type.get_canonical().spelling))


def holds_node_handle(type_):
    """Whether a type is a ROS 1 NodeHandle or a (smart) pointer to one.

    ``ros::NodeHandle&``, ``ros::NodeHandle*``, and a class template of
    one argument that is the handle (``shared_ptr<ros::NodeHandle>``, by
    value or reference): what a function returning a handle returns.
    """
    canonical = type_.get_canonical()
    if canonical.kind in (ci.TypeKind.LVALUEREFERENCE,
                          ci.TypeKind.RVALUEREFERENCE):
        canonical = canonical.get_pointee().get_canonical()
    if _NODE_HANDLE_TYPE.match(canonical.spelling):
        return True
    return canonical.get_num_template_arguments() == 1 and bool(
        _NODE_HANDLE_TYPE.match(
            canonical.get_template_argument_type(0).get_canonical().spelling))


# std::/boost:: functions whose result is their argument, by reference
_PASS_THROUGH = frozenset({'ref', 'cref', 'move', 'forward'})


def plain_handle(cursor):
    """The variable an expression is, when it is one and no more.

    ``nh``, ``*nh``, ``this->nh_``, ``ptr.get()``, and what passes the
    object itself on (``boost::ref(nh)``, ``std::move(nh)``): the handle; a
    value made of it (``ros::NodeHandle(nh, "sub")``, ``f(i)``) is another
    object.
    """
    if cursor is None:
        return None
    tokens = [t.spelling for t in source_tokens(cursor)]
    while len(tokens) > 5 and tokens[1] == '::' and \
            tokens[2] in _PASS_THROUGH and tokens[-1] == ')':
        tokens = tokens[tokens.index('(') + 1:-1]
    while tokens and tokens[0] in ('*', '&'):
        tokens = tokens[1:]
    if tokens[:2] == ['this', '->']:
        tokens = tokens[2:]
    if tokens[-4:] in (['.', 'get', '(', ')'], ['->', 'get', '(', ')']):
        tokens = tokens[:-4]
    if len(tokens) != 1:
        return None
    return first_handle(cursor)


def template_member(function):
    """The function as the package's source defines it.

    ``Filter<Ekf> f(nh); f.run();`` references ``Filter<Ekf>::run`` and
    ``helper(3)`` references ``helper<int>``: instantiations, whose USRs
    are not those of the ``Filter<T>::run`` and ``helper<T>`` the walk
    defines. Calls and bindings go to the template, where the facts are
    (a member template of a class template takes two steps). Any other
    function is itself.
    """
    for _ in range(3):
        template = ci.conf.lib.clang_getSpecializedCursorTemplate(function)
        if template is None or template.kind not in FUNCTION_KINDS or \
                template == function:
            break
        function = template
    return function


def first_function(cursor):
    """The function a callable expression names (``&C::f``, ``f``)."""
    for current in [cursor] + list(walk_preorder(cursor)):
        if current.kind in REF_KINDS and current.referenced is not None and \
                current.referenced.kind in FUNCTION_KINDS:
            return current.referenced
    return None


def _callee(call):
    """The expression a call calls (its first child), or None."""
    children = child_cursors(call)
    return children[0] if children else None


def call_object(call):
    """The object expression of a member call, or None."""
    callee = _callee(call)
    if callee is not None and callee.kind == CK.MEMBER_REF_EXPR:
        for child in child_cursors(callee):
            if child.kind not in (CK.TYPE_REF, CK.NAMESPACE_REF,
                                  CK.TEMPLATE_REF):
                return child
    return None


def explicit_template_type(call):
    """The first explicit template argument written at a call site."""
    callee = _callee(call)
    if callee is None:
        return None
    candidates = [callee] + child_cursors(callee)
    if callee.kind == CK.UNEXPOSED_EXPR and child_cursors(callee):
        candidates += child_cursors(child_cursors(callee)[0])
    # not the class of a static member (`ros::SubscribeOptions::create<M>`)
    owner = call.referenced.semantic_parent \
        if call.referenced is not None else None
    # a dependent call refers to nothing: only what follows its `<` is a
    # template argument (`Base::create_publisher<M>`, not `Base`)
    arguments_from = -1
    if call.referenced is None:
        opening = [t for t in source_tokens(callee) if t.spelling == '<']
        if not opening:
            return None
        arguments_from = opening[0].extent.start.offset
    for child in candidates:
        if child.kind == CK.TYPE_REF and not (
                owner is not None and same_cursor(child.referenced, owner)) \
                and child.extent.start.offset > arguments_from:
            return child.type.spelling or child.spelling
    return None


def expression_text(cursor):
    """The source text of an expression, tokens joined readably."""
    text = ''
    previous = ''
    for token in source_tokens(cursor):
        spelling = token.spelling
        if previous and (previous[-1].isalnum() or previous[-1] == '_') \
                and (spelling[0].isalnum() or spelling[0] == '_'):
            text += ' '
        text += spelling
        previous = spelling
    return text


def callback_msg_type(declaration):
    """The message type a callback's declaration takes, or None."""
    if declaration is None:
        return None
    for child in declaration.get_children():
        if child.kind == CK.PARM_DECL:
            return normalize_msg_type(child.type.spelling)
    return None


_CALLABLE_ARGUMENT = re.compile(
    r'\(lambda at |std::_Bind|std::function<|boost::_bi::bind_t|'
    r'\(\*\)\(|::\*\)\(')


def is_callable_argument(argument):
    """A lambda, bind result, std::function or function (pointer)."""
    kind = argument.type.get_canonical().kind
    if kind in (ci.TypeKind.FUNCTIONPROTO, ci.TypeKind.MEMBERPOINTER):
        return True
    return bool(_CALLABLE_ARGUMENT.search(
        argument.type.get_canonical().spelling))


def is_duration(argument):
    """Whether an argument is a duration (std::chrono or rclcpp)."""
    return is_chrono_duration(argument.type) or \
        'rclcpp::Duration' in argument.type.get_canonical().spelling


def is_written(argument):
    """Whether an argument is written at the call (a default has no tokens)."""
    return next(iter(argument.get_tokens()), None) is not None


def role_argument(arguments, position):
    """The argument of a call that has a role of ros_api, or None.

    `position` is an index or one of ros_api's "first argument of this
    kind" markers (the first string, callable, duration); an argument the
    code left to its default is None.
    """
    by_type = {
        ros_api.FIRST_STRING: is_string,
        ros_api.FIRST_CALLABLE: is_callable_argument,
        ros_api.FIRST_DURATION: is_duration,
    }.get(position)
    if by_type is not None:
        return next((a for a in arguments if by_type(a)), None)
    if isinstance(position, int) and position < len(arguments):
        argument = arguments[position]
        return argument if is_written(argument) else None
    return None


def call_arguments(call):
    """The arguments a call passes to its callee's parameters.

    A call of a member ``operator()`` (a functor; a catch-all's field
    called like a method, ``helper->advertise(nh, "out", 1)``) lists the
    object called as its first argument: it is no parameter's, and is
    left out (it is the expression the call starts with).
    """
    arguments = list(call.get_arguments())
    ref = call.referenced
    if arguments and ref is not None and ref.spelling == 'operator()' and \
            ref.kind in (CK.CXX_METHOD, CK.FUNCTION_TEMPLATE) and \
            arguments[0].extent.start.offset == call.extent.start.offset:
        return arguments[1:]
    return arguments


def written_arguments(arguments):
    """The arguments written at a call (defaulted ones left out)."""
    return [a for a in arguments if is_written(a)]


def is_string(argument):
    """Whether an expression or declaration is a string (or chars)."""
    spelling = argument.type.get_canonical().spelling
    return 'basic_string' in spelling or 'char' in spelling


def initializer(variable):
    """The expression a variable or field is initialised with, or None."""
    init = [c for c in variable.get_children()
            if c.kind not in (CK.TYPE_REF, CK.NAMESPACE_REF, CK.TEMPLATE_REF)]
    return init[0] if len(init) == 1 else None


def is_logical(cursor, operands):
    """Whether a binary operator is ``||`` or ``&&`` (short-circuiting)."""
    if len(operands) != 2:
        return False
    # only the tokens between the operands: the operator
    between = ci.SourceRange.from_locations(
        operands[0].extent.end, operands[1].extent.start)
    return any(t.spelling in ('||', '&&', 'or', 'and')
               for t in cursor.translation_unit.get_tokens(extent=between))


def continue_before(loop, sleep):
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


def overloaded_declarations(reference):
    """The declarations an OVERLOADED_DECL_REF cursor names.

    (cindex's Cursor lacks the calls.)
    """
    library = ci.conf.lib
    return [library.clang_getOverloadedDecl(reference, index)
            for index in range(library.clang_getNumOverloadedDecls(reference))]


def overload_candidate(call):
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
        candidates = overloaded_declarations(current)
        names = {qualified_name(c) for c in candidates}
        if candidates and len(names) == 1:
            return candidates[0]
        return None
    return None


def made_class(call):
    """The declaration of X in a ``make_shared<X>(...)`` call, or None."""
    made = call.type.get_canonical()
    if made.get_num_template_arguments() < 1:
        return None
    declaration = made.get_template_argument_type(0).get_declaration()
    if declaration is None or declaration.kind == CK.NO_DECL_FOUND:
        return None
    return declaration


def declared_in(declaration, loop):
    """Whether a declaration lies inside a loop's source range."""
    declared = declaration.extent.start
    return declared.file is not None and \
        loop.extent.start.file is not None and \
        declared.file.name == loop.extent.start.file.name and \
        loop.extent.start.offset <= declared.offset <= loop.extent.end.offset


# what the model mode's repairs declare an unknown library's classes and
# members with (model_headers/rsia_model/message.h)
REPAIRED_PREFIX = 'rsia_model::'
# the constructor the repaired classes inherit (`using Unknown::Unknown`)
REPAIRED_CONSTRUCTOR = 'Unknown'


def declared_by_catch_all(cursor):
    """Whether the model mode's catch-alls declare it (repairs, stand-ins).

    Such a declaration says nothing of what it declares but its name.
    """
    location = cursor.location
    if location.file is None:
        return False
    path = location.file.name.replace(os.sep, '/')
    return any(f'/{directory}/'.replace(os.sep, '/') in path
               for directory in CATCH_ALL_DIRS)


def repaired_call_name(call, ref):
    """The API a call into a repaired stand-in names, as written.

    A class of a library that is neither installed nor modelled is
    declared by the repairs as a ``rsia_model::Unknown`` whose members are
    ``rsia_model::Any`` objects: ``Poller<M>::create_subscription(...)``
    then calls ``Any::operator()`` and ``Poller<M>{node, "t"}`` the
    inherited ``Unknown`` constructor. The name the code wrote
    (``ns::Poller::create_subscription``, ``ns::Poller::Poller``) is what
    the API table knows.
    """
    if ref.kind in (CK.CONSTRUCTOR, CK.FUNCTION_TEMPLATE) and \
            ref.spelling == REPAIRED_CONSTRUCTOR:
        made = call.type.get_canonical().get_declaration()
        if made is None or made.kind not in CLASS_KINDS or \
                qualified_name(made).startswith(REPAIRED_PREFIX):
            return None
        return f'{qualified_name(made)}::{made.spelling}'
    if ref.spelling != 'operator()':
        return _through_qualifying_class(call, ref)
    for current in walk_preorder(call):
        if current.kind in REF_KINDS:
            member = current.referenced
            if member is not None and member.kind in (
                    CK.VAR_DECL, CK.FIELD_DECL) and \
                    member.semantic_parent is not None and \
                    member.semantic_parent.kind in CLASS_KINDS:
                name = qualified_name(member)
                if name.startswith(REPAIRED_PREFIX):
                    # a name every catch-all has: the class of the object
                    # it is reached through names the API, when the table
                    # knows it (else the name alone, see walker._call)
                    written = _member_of_object_class(current, member)
                    return written if written and \
                        ros_api.lookup_call(written) else name
                return name
            return None
    return None


def _member_of_object_class(member_ref, member):
    """``ns::C::name`` of a member reached through an object of class C.

    (``plugin->advertise(...)`` on a ``shared_ptr<ns::C>`` of a class the
    repairs declared: the member is the catch-all's, the class the code's.)
    """
    children = child_cursors(member_ref)
    if member_ref.kind != CK.MEMBER_REF_EXPR or not children:
        return None
    operand = children[0]
    while True:
        written = normalize_msg_type(operand.type.get_canonical().spelling)
        owner = re.sub(r'<.*', '', written or '')
        inner = child_cursors(operand)
        # (past the implicit conversion to the catch-all base that holds
        # the member)
        if not owner.startswith(REPAIRED_PREFIX) or len(inner) != 1:
            break
        operand = inner[0]
    if not owner or owner.startswith(REPAIRED_PREFIX) or \
            not re.fullmatch(r'[\w:]+', owner):
        return None
    return f'{owner}::{member.spelling}'


def _through_qualifying_class(call, ref):
    """The API a catch-all's member called through a class names.

    ``Poller<M>::create_subscription(this, "t", qos)`` on a repaired class
    calls the static member template every catch-all has: the class that
    qualifies the call, as written, names the API.
    """
    for current in walk_preorder(call):
        if current.kind not in REF_KINDS:
            continue
        if current.kind != CK.DECL_REF_EXPR or \
                current.spelling != ref.spelling:
            return None
        children = list(current.get_children())
        scope = next((child for child in children
                      if child.kind in (CK.TEMPLATE_REF, CK.TYPE_REF)), None)
        owner = qualified_name(scope.referenced) \
            if scope is not None and scope.referenced is not None else ''
        if owner.endswith('::element_type'):
            # `decltype(sub_)::element_type::create_subscription(...)`: the
            # class whose pointer type the operand of decltype is declared
            # with (`Poller<M>::SharedPtr sub_;`)
            operand = next((c for c in children if c.kind in REF_KINDS),
                           None)
            pointer = _POINTER_OF_CLASS.match(re.sub(
                r'<.*>', '', operand.type.spelling)) if operand else None
            owner = pointer.group(1) if pointer else ''
        return f'{owner}::{ref.spelling}' \
            if owner and not owner.startswith(REPAIRED_PREFIX) else None
    return None


# a class's pointer type by ROS convention, spelled without template
# arguments: `autoware_utils::InterProcessPollingSubscriber::SharedPtr`
_POINTER_OF_CLASS = re.compile(
    r'^(?:const\s+)?((?:\w+::)*\w+)::(?:Const)?(?:Shared)?Ptr$')


def base_class_names(cursor):
    """The qualified names of a class's direct bases, without arguments."""
    return base_class_names_of(cursor.get_children())


def base_class_names_of(children):
    """The qualified names of the base specifiers among `children`."""
    names = []
    for child in children:
        if child.kind != CK.CXX_BASE_SPECIFIER:
            continue
        base = child.type.get_declaration()
        if base is not None and base.kind != CK.NO_DECL_FOUND:
            names.append(qualified_name(base))
        else:
            names.append(re.sub(r'<.*', '', child.type.spelling))
    return [name for name in names if name]


def all_base_class_names(cursor, depth=8):
    """The qualified names of a class's bases, theirs, and so on.

    A base the parse could not declare (its header missing) is no base
    specifier of the class: its name is read from the class's head.
    """
    names = set(written_base_names(cursor))
    for child in cursor.get_children():
        if child.kind != CK.CXX_BASE_SPECIFIER:
            continue
        names.update(base_class_names_of([child]))
        base = child.type.get_declaration()
        if depth and base is not None and base.kind in CLASS_KINDS:
            names |= all_base_class_names(base, depth - 1)
    return names


def written_base_names(cursor):
    """The base names a class's head writes (``class C : public ns::B<T>``).

    Without template arguments; as written (the namespace may be left out).
    """
    head = []
    for token in cursor.get_tokens():
        if token.spelling == '{':
            break
        head.append(token.spelling)
    names = []
    depth = 0
    current = None
    for token in head:
        depth += token.count('<') - token.count('>')
        if depth:
            continue
        if token == ':' and current is None:
            current = []
        elif token == ',' and current is not None:
            names.append(''.join(current))
            current = []
        elif current is not None and token not in (
                'public', 'protected', 'private', 'virtual', '>'):
            current.append(token)
    if current:
        names.append(''.join(current))
    return [name.lstrip(':') for name in names if name]


def aliased_class(cursor):
    """The class ``typedef Controller<Iface> JointController;`` names.

    A template's specialisation has the template's qualified name; None
    when the alias names no class.
    """
    declaration = cursor.underlying_typedef_type.get_canonical() \
        .get_declaration()
    if declaration is None or declaration.kind not in CLASS_KINDS:
        return None
    return declaration


def top_level_scopes(tokens):
    """Positions of the `::` of a name outside its template arguments."""
    depth = 0
    scopes = []
    for i, token in enumerate(tokens):
        depth += token.count('<') - token.count('>')
        if token == '::' and depth == 0:
            scopes.append(i)
    return scopes
