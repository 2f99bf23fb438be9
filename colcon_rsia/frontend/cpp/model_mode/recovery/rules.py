# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The rules: from a clang diagnostic to the declarations that fix it."""

from dataclasses import dataclass
import os
import re
from typing import Callable
from typing import FrozenSet
from typing import Optional
from typing import Tuple

from colcon_rsia.frontend.cpp.model_mode.recovery import overlay
from colcon_rsia.frontend.cpp.model_mode.recovery.declared import aliases_of
from colcon_rsia.frontend.cpp.model_mode.recovery.declared import included
from colcon_rsia.frontend.cpp.model_mode.recovery.declared import is_declared
from colcon_rsia.frontend.cpp.model_mode.recovery.declared import one_kind_each
from colcon_rsia.frontend.cpp.model_mode.recovery.declared import reopened_namespace
from colcon_rsia.frontend.cpp.model_mode.recovery.declared import unaliased
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import ALL_CAPS
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import CAMEL
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import CONSTANT
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import declared_as_variable
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import FUNCTION
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import INCLUDES
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import KEYWORDS
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import LITERAL
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MACRO_CONDITION
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MACRO_EMPTY
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MACRO_FUNCTION
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MACRO_VALUE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MACRO_VOID
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MEMBER
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MEMBER_SCOPE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MEMBER_TEMPLATE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MEMBER_TYPE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MODEL_MEMBER
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import NAMESPACE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import NO_HASH
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import NO_OVERRIDE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import OBJECT
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import SPECIALIZED
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import STD_HEADER
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import TEMPLATE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import TEMPLATE_USE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import TYPE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import VALUE
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import ARGUMENT_NOT_VALUE
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import ARRAY_TYPE_ARGUMENT
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import CALLED_NON_FUNCTION
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import DECLARATION_EXPECTED
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import HASH_REDEFINED
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import IN_CLASS
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import IN_NAMESPACE
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import IN_STD
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import INCOMPLETE
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import LITERAL_OPERATOR
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import MACRO_STATEMENT
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import NAMESPACE_ALIAS
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import NAMESPACE_AS_VALUE
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import NO_MATCHING_MEMBER
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import NOT_A_SCOPE
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import NOT_A_TEMPLATE
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import OVERRIDE
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import RESERVED_ATTRIBUTE
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import SPECIALIZATION
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import TYPE_IN_CLASS
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import UNDECLARED
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import UNDEFINED_IN_STD
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import UNDEFINED_MACRO
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import UNKNOWN_TEMPLATE
from colcon_rsia.frontend.cpp.model_mode.recovery.messages import UNKNOWN_TYPE
from colcon_rsia.frontend.cpp.model_mode.recovery.naming import after_name
from colcon_rsia.frontend.cpp.model_mode.recovery.naming import by_qualified_use
from colcon_rsia.frontend.cpp.model_mode.recovery.naming import by_use
from colcon_rsia.frontend.cpp.model_mode.recovery.naming import CAST_TYPE
from colcon_rsia.frontend.cpp.model_mode.recovery.naming import in_macro_arguments
from colcon_rsia.frontend.cpp.model_mode.recovery.naming import names_nested_type
from colcon_rsia.frontend.cpp.model_mode.recovery.naming import namespace_at
from colcon_rsia.frontend.cpp.model_mode.recovery.naming import next_line
from colcon_rsia.frontend.cpp.model_mode.recovery.naming import opens_body
from colcon_rsia.frontend.cpp.model_mode.recovery.naming import qualified
from colcon_rsia.frontend.cpp.model_mode.recovery.naming import QUOTED_NAME
from colcon_rsia.frontend.cpp.model_mode.recovery.naming import template_shape
from colcon_rsia.frontend.cpp.model_mode.recovery.naming import template_use
from colcon_rsia.frontend.cpp.model_mode.recovery.naming import uses_of_namespace
from colcon_rsia.frontend.cpp.model_mode.recovery.std_headers import \
    STD_HEADER_OF
from colcon_rsia.frontend.cpp.model_mode.source_names import template_kind
from colcon_rsia.frontend.cpp.model_mode.unknown_headers import UNKNOWN_DIR


@dataclass
class Seen:
    """One diagnostic, and the code it is about.

    `text` is the line that spells the name the message is about (for a
    name in a macro's arguments, the line it is on, not the line the call
    starts on), `column` its place there, `subject` the first quoted name
    of the message and `after` the code that follows it.
    """

    message: str
    file: str
    line: int
    column: int
    text: str
    subject: str
    after: str
    read_line: Callable
    texts: tuple
    stand_in: Optional[Callable]
    # (message, file, line, column) of clang's notes to the error, where
    # the rules need them (see NEEDS_NOTES)
    notes: tuple = ()

    @property
    def before(self):
        """The code of the line before the name."""
        return self.text[:max(0, self.column - 1)]


@dataclass(frozen=True)
class Example:
    """A worked example of a rule: one line of code and clang's message.

    `column` is where clang puts the error (1-based, as clang counts);
    `expected` the (kind, name) repairs the rule makes of it.
    """

    code: str
    message: str
    column: int
    expected: FrozenSet[Tuple[str, str]]


@dataclass(frozen=True)
class Rule:
    """One row of the table: a class of diagnostics and what answers it.

    `applies(seen)` says whether the diagnostic is of the rule's class
    (then no later rule sees it); `decide(seen)` gives the (kind, name)
    repairs that would fix it, possibly none.
    """

    id: str
    answers: str        # the diagnostic class, in words
    produces: tuple     # the kinds its repairs have
    applies: Callable
    decide: Callable
    examples: tuple = ()


def _message(pattern):
    return lambda seen: pattern.search(seen.message) is not None


# --- the rules, in the order they are tried --------------------------------

def _reserved_attribute(seen):
    """A name reserved to the implementation, `__name__`, at an error.

    An attribute macro of a compiler we are not (`void __device__ f()`,
    `__launch_bounds__(256)`), read as a type or as a variable of type void.
    """
    match = RESERVED_ATTRIBUTE.match(seen.text, max(0, seen.column - 1))
    return {(MACRO_VOID if match.group(2) else MACRO_EMPTY, match.group(1))}


def _reserved_attribute_applies(seen):
    match = RESERVED_ATTRIBUTE.match(seen.text, max(0, seen.column - 1))
    return match is not None and \
        seen.subject in (None, 'void', match.group(1))


# what clang says where a declarator goes on with an unknown macro's call
_DECLARATOR_ENDS = re.compile(
    r"^expected ';' (?:at end of declaration list|after top level "
    r'declarator|at end of declaration)$|^expected function body after '
    r'function declarator$')
_MACRO_AT = re.compile(r'\s*([A-Z][A-Z0-9]*_[A-Z0-9_]*)\s*(\()?')


def _attribute_macro_applies(seen):
    return _DECLARATOR_ENDS.match(seen.message) is not None and \
        _MACRO_AT.match(seen.text, max(0, seen.column - 1)) is not None


def _attribute_macro(seen):
    """An unknown ALL_CAPS macro after a declarator: an attribute's.

    `Data get() LOCKED_BY(mutex_);`, `void f() NO_THROW;`: the declaration
    ends where the macro is, so it expands to nothing.
    """
    match = _MACRO_AT.match(seen.text, max(0, seen.column - 1))
    return {(MACRO_VOID if match.group(2) else MACRO_EMPTY, match.group(1))}


def _undeclared(seen):
    """An undeclared name: a kind from how the code uses it."""
    written = UNDECLARED.match(seen.message).group(1)
    kind, name = by_use(written, seen.after, unqualified=True,
                        texts=seen.texts)
    if written not in seen.text and not CAMEL.match(name):
        # spelled in a macro's body (the macro's expansion names a
        # namespace): a namespace, by far the most common
        kind = NAMESPACE
    elif written not in seen.text and ALL_CAPS.match(name) and \
            any(re.search(r'\b' + name + r'\s*\(', t) for t in seen.texts):
        # a macro that a macro's body calls: a function-like macro
        kind = MACRO_VALUE
    elif kind == OBJECT and (
            CAST_TYPE.search(seen.before + '@' + seen.after) or (
                seen.before.rstrip().endswith('<') and
                seen.after.startswith(('>', ',')))):
        # static_cast<uchar>(v), (uchar)v, Point3_<uchar>: a type
        kind = TYPE
    # an undeclared lower-case variable is most often a local or a member
    # whose declaration failed (an error of its own): declaring a global of
    # that name would only hide the cause. One the code never declares is
    # a library's (a C constant, an unknown base class's member)
    if kind != OBJECT or not declared_as_variable(name, seen.texts):
        return {(kind, name)}
    return set()


def _unknown_type(seen):
    """An unknown type name; an ALL_CAPS one is a macro at declaration level."""
    name = qualified(UNKNOWN_TYPE.match(seen.message).group(1), seen.text,
                     seen.column)
    if ALL_CAPS.match(name) and '_' in name:
        # FOO_EXPORT class X, FOO_CLASS_EXPORT(X)
        return {(MACRO_VOID if seen.after.startswith('(') else MACRO_EMPTY,
                 name)}
    return {(template_kind(seen.after) if seen.after.startswith('<')
             else TYPE, name)}


def _unknown_template(seen):
    match = UNKNOWN_TEMPLATE.match(seen.message)
    return {(template_kind(seen.after), qualified(
        match.group(1) or match.group(2), seen.text, seen.column))}


def _namespace_as_value(seen):
    """A class whose constants made it look like a namespace."""
    # the names repaired inside it become its members
    return {(TYPE, qualified(NAMESPACE_AS_VALUE.match(seen.message).group(1),
                             seen.text, seen.column))}


def _standard_header(seen):
    """A standard name the real headers would have brought in on the way."""
    match = IN_STD.match(seen.message) or \
        UNDEFINED_IN_STD.match(seen.message)
    # `std::filesystem::path`: the nested namespace names its header too
    for name in (match.group(1), match.groupdict().get('inner')):
        header = STD_HEADER_OF.get(name or '')
        if header:
            return {(STD_HEADER, header)}
    return set()


def _incomplete(seen):
    """A class only forward-declared: its definition is generated."""
    match = INCOMPLETE.search(seen.message)
    name = match.group(1) or match.group(2)
    if ALL_CAPS.match(name) and '_' in name:
        # `struct FOO_ALIGN16 Point {`: an attribute's macro
        return {(MACRO_EMPTY, name)}
    return {(TYPE, name)}


def _model_member(class_name, member, seen):
    """A member a model class lacks: added to it (overlay.py), or None."""
    if overlay.model_class(class_name) is None:
        return None
    if seen.after.startswith('<'):
        shape = overlay.FUNCTION_SHAPE  # a member template called
    elif CAMEL.match(member) and (
            names_nested_type(seen.after, seen.before) or
            seen.after.startswith('::')) or \
            TYPE_IN_CLASS.match(seen.message):
        shape = overlay.TYPE_SHAPE
    elif seen.after.startswith('('):
        shape = overlay.FUNCTION_SHAPE
    else:
        shape = overlay.VALUE_SHAPE
    return {(f'{MODEL_MEMBER}:{shape}', f'{class_name}::{member}')}


def _member_of_class(seen):
    """A member of a class: added to a model class, declared in a repaired.

    A class of the model lacks what the user's library version has; a
    class a repair declared gets the members the code names (added only if
    one did).
    """
    match = IN_CLASS.match(seen.message)
    found = _model_member(match.group(2), match.group(1), seen)
    if found is not None:
        return found
    nested = CAMEL.match(match.group(1)) and names_nested_type(
        seen.after, seen.before)
    kind = MEMBER_TYPE if nested else \
        MEMBER_TEMPLATE if seen.after.startswith('<') else \
        MEMBER_SCOPE if seen.after.startswith('::') and \
        CAMEL.match(match.group(1)) else MEMBER
    return {(kind, f'{match.group(2)}::{match.group(1)}')} | \
        unknown_owner(match, seen.stand_in)


def _type_in_class(seen):
    """A nested type of a class a repair declared (`Class::Ptr`).

    A base class's function called as a statement (`Base::f(x);`) is read
    as a declaration of `x` first: a lower-case name called is a function.
    """
    match = TYPE_IN_CLASS.match(seen.message)
    found = _model_member(match.group(2), match.group(1), seen)
    if found is not None:
        return found
    called = seen.after.startswith('(') and not CAMEL.match(match.group(1))
    return {(MEMBER if called else MEMBER_TYPE,
             f'{match.group(2)}::{match.group(1)}')} | \
        unknown_owner(match, seen.stand_in)


def _name_in_namespace(seen):
    """A name of a namespace that exists but lacks it."""
    what, name, namespace = IN_NAMESPACE.match(seen.message).groups()
    after = seen.after
    if what == 'type' and after.startswith('(') and not CAMEL.match(name):
        # `ns::correct(polygon);` read as a declaration of `polygon`: a
        # lower-case name called is a function
        kind = FUNCTION
    elif what in ('type', 'class', 'template') and after.startswith('<'):
        kind = template_use(name, after, unqualified=False, texts=seen.texts)
    elif what in ('type', 'class'):
        kind = TYPE
    elif what == 'template':
        kind = template_shape(after, seen.texts)
    else:
        kind = by_qualified_use(name, after, seen.before, seen.texts)
    return {(kind, f'{namespace}::{name}')}


def _model_overload(seen):
    """A call no overload of a model class's method matches.

    The user's version of the library has the overload (a getter beside
    the setter, another parameter type): the class, named by the notes of
    its candidates, gets one that takes anything.
    """
    name = NO_MATCHING_MEMBER.match(seen.message).group(1)
    for _, file, line, _ in seen.notes:
        class_name = overlay.model_class_at(file, line) if file else None
        if class_name is not None:
            return {(f'{MODEL_MEMBER}:{overlay.FUNCTION_SHAPE}',
                     f'{class_name}::{name}')}
    return set()


def _not_a_template(seen):
    """A member declared as a value, then used with template arguments."""
    return {(TEMPLATE_USE, NOT_A_TEMPLATE.match(seen.message).group(1))}


def _unknown_scope(seen):
    """An unknown scope (`::gen::Params` of a generated header)."""
    match = NOT_A_SCOPE.match(seen.message)
    if match.group(1) or seen.after.startswith('::'):
        name = qualified(match.group(1), seen.text, seen.column) \
            if match.group(1) else match.group(3)
        return {(NAMESPACE, name)}
    # `::cFree(p)`, `::c_type_t`: a C library's global name
    what, name = match.group(2), match.group(3)
    kind = TYPE if what == 'type' else template_kind(seen.after) \
        if what == 'template' else by_use(
            name, seen.after, unqualified=False)[0]
    return {(kind, name)}


def _undefined_macro(seen):
    """`#if FOO(1, 2)` with FOO undefined: a macro that holds."""
    return {(MACRO_CONDITION, UNDEFINED_MACRO.match(seen.message).group(1))}


def _specialization(seen):
    """A function template the code specialises, in its namespace."""
    namespace = namespace_at(seen.read_line, seen.file, seen.line)
    return {(SPECIALIZED, '::'.join(filter(None, (
        namespace, SPECIALIZATION.match(seen.message).group(1)))))}


def _base_class(seen):
    """`class Label : public Widget` with Widget undeclared.

    The column is at the base's name (or at its last part:
    `ns::|Widget`).
    """
    match = re.match(r'\s*(?:::\s*)?([A-Za-z_]\w*(?:\s*::\s*[A-Za-z_]\w*)*)'
                     r'\s*(<?)', seen.text[max(0, seen.column - 1):])
    if not match:
        return set()
    name = qualified(re.sub(r'\s+', '', match.group(1)), seen.text,
                     seen.column)
    rest = seen.text[max(0, seen.column - 1) + match.start(2):]
    return {(template_kind(rest) if match.group(2) else TYPE, name)}


def _macro_with_body_applies(seen):
    match = MACRO_STATEMENT.match(seen.text)
    return match is not None and (
        seen.message == 'expected unqualified-id' or
        DECLARATION_EXPECTED.match(seen.message)) and opens_body(
        seen.read_line, seen.file, seen.line, seen.text, match.end())


def _macro_with_body(seen):
    """`FOO(name, m) { ... }` at namespace level: the head of a function."""
    return {(MACRO_FUNCTION, MACRO_STATEMENT.match(seen.text).group(1))}


def _macro_statement_applies(seen):
    return MACRO_STATEMENT.match(seen.text) is not None and \
        DECLARATION_EXPECTED.match(seen.message) is not None


def _macro_statement(seen):
    """`FOO_REGISTER(...)` at namespace level, read as a declaration."""
    return {(MACRO_VOID, MACRO_STATEMENT.match(seen.text).group(1))}


def _no_override(seen):
    """`override` of a method whose base class is unknown: a no-op."""
    return {(NO_OVERRIDE, 'override')}


def _literal_or_hash(seen):
    """A user-defined literal's operator; a hash the package specialises."""
    match = LITERAL_OPERATOR.match(seen.message)
    if match:
        return {(LITERAL, match.group(1))}
    return {(NO_HASH, HASH_REDEFINED.match(seen.message).group(1))}


def _argument_not_value(seen):
    """A macro's argument read as a value where the macro is missing."""
    macro = re.search(r'\b([A-Z][A-Z0-9_]*)\s*\(\s*$', seen.before)
    if macro:
        # FOO_NVP(Base): the argument is a type, the macro is missing
        return {(MACRO_VALUE, macro.group(1))}
    if seen.subject and seen.message.startswith(f"'{seen.subject}'"):
        # an enumerator of an unknown base class, which its CamelCase made
        # a class of ours: a constant
        return {(VALUE, qualified(seen.subject, seen.text, seen.column))}
    return set()


def _macro_arguments_called_applies(seen):
    match = MACRO_STATEMENT.match(seen.text)
    return match is not None and \
        CALLED_NON_FUNCTION.match(seen.message) is not None and \
        seen.column > match.end()


def _macro_arguments_called(seen):
    """`FOO_EXIT((&a)(&b)) { ... }`: an unknown macro's arguments called."""
    return {(MACRO_VOID, MACRO_STATEMENT.match(seen.text).group(1))}


def _array_element_applies(seen):
    return seen.message == 'expected expression' and \
        seen.text[seen.column - 1:seen.column] == ']'


def _array_element(seen):
    """`std::unique_ptr<info_t[]>`: an unknown name read as a value."""
    match = ARRAY_TYPE_ARGUMENT.search(seen.text[:seen.column - 1])
    return {(TYPE, match.group(1))} if match else set()


def _namespace_alias(seen):
    """`namespace fs = lib::fs;`, `using namespace lib;` of a lacking lib."""
    return {(NAMESPACE, (match.group(1) or match.group(2)).rstrip(':'))
            for match in NAMESPACE_ALIAS.finditer(seen.text)
            if (match.group(1) or match.group(2)).rstrip(':')}


def _examples(*rows):
    return tuple(Example(code, message, column, frozenset(expected))
                 for code, message, column, expected in rows)


RULES = (
    Rule('reserved-attribute', 'a `__name__` attribute of another compiler',
         (MACRO_EMPTY, MACRO_VOID), _reserved_attribute_applies,
         _reserved_attribute, _examples(
             ('void __kernel__ scale(float * x);',
              "variable has incomplete type 'void'", 6,
              {(MACRO_EMPTY, '__kernel__')}))),
    Rule('attribute-macro', 'an unknown macro after a declarator',
         (MACRO_VOID, MACRO_EMPTY), _attribute_macro_applies,
         _attribute_macro, _examples(
             ('  Data get() const GUARDED_BY(mutex_);',
              "expected ';' at end of declaration list", 20,
              {(MACRO_VOID, 'GUARDED_BY')}))),
    Rule('undeclared-name', 'use of undeclared identifier',
         (NAMESPACE, TYPE, FUNCTION, OBJECT, CONSTANT, MACRO_VALUE),
         _message(UNDECLARED), _undeclared, _examples(
             ('  lib::Widget w;', "use of undeclared identifier 'lib'", 3,
              {(NAMESPACE, 'lib')}),
             ('  int flags = LIB_FLAG_FAST;',
              "use of undeclared identifier 'LIB_FLAG_FAST'", 15,
              {(CONSTANT, 'LIB_FLAG_FAST')}))),
    Rule('unknown-type', 'unknown type name', (TYPE, TEMPLATE, MACRO_EMPTY,
                                               MACRO_VOID),
         _message(UNKNOWN_TYPE), _unknown_type, _examples(
             ('  Widget * w = nullptr;', "unknown type name 'Widget'", 3,
              {(TYPE, 'Widget')}),
             ('class LIB_EXPORT Thing {};', "unknown type name 'LIB_EXPORT'",
              7, {(MACRO_EMPTY, 'LIB_EXPORT')}))),
    Rule('unknown-template', 'unknown template name', (TEMPLATE,),
         _message(UNKNOWN_TEMPLATE), _unknown_template, _examples(
             ('  Grid<float> grid;', "no template named 'Grid'", 3,
              {(TEMPLATE, 'Grid')}))),
    Rule('namespace-as-value', 'a namespace named where a value is expected',
         (TYPE,), _message(NAMESPACE_AS_VALUE), _namespace_as_value,
         _examples(
             ('  auto f = Font("Sans", 10);',
              "unexpected namespace name 'Font': expected expression", 12,
              {(TYPE, 'Font')}))),
    Rule('standard-header', 'a standard name of a header not included',
         (STD_HEADER,), lambda seen: bool(
             IN_STD.match(seen.message) or
             UNDEFINED_IN_STD.match(seen.message)),
         _standard_header, _examples(
             ('  std::optional<int> o;',
              "no template named 'optional' in namespace 'std'", 8,
              {(STD_HEADER, 'optional')}),
             ('  std::filesystem::path p;',
              "no type named 'path' in namespace 'std::filesystem'", 20,
              {(STD_HEADER, 'filesystem')}))),
    Rule('incomplete-type', 'a class used but only declared', (TYPE,
                                                               MACRO_EMPTY),
         _message(INCOMPLETE), _incomplete, _examples(
             ('  Index index;', "variable has incomplete type 'Index'", 9,
              {(TYPE, 'Index')}))),
    Rule('member-of-class', 'no member named in a class',
         (MEMBER, MEMBER_TYPE, MEMBER_TEMPLATE, MEMBER_SCOPE, MODEL_MEMBER),
         _message(IN_CLASS), _member_of_class, _examples(
             ('  int n = lib::Grid::size();',
              "no member named 'size' in 'lib::Grid'", 22,
              {(MEMBER, 'lib::Grid::size')}))),
    Rule('type-in-class', 'no type named in a class',
         (MEMBER, MEMBER_TYPE, MODEL_MEMBER), _message(TYPE_IN_CLASS),
         _type_in_class,
         _examples(
             ('  lib::Grid::Ptr grid;', "no type named 'Ptr' in 'lib::Grid'",
              14, {(MEMBER_TYPE, 'lib::Grid::Ptr')}))),
    Rule('name-in-namespace', 'no name in a namespace that exists',
         (TYPE, TEMPLATE, FUNCTION, OBJECT, CONSTANT, NAMESPACE),
         _message(IN_NAMESPACE), _name_in_namespace, _examples(
             ('  lib::draw(canvas);',
              "no member named 'draw' in namespace 'lib'", 8,
              {(FUNCTION, 'lib::draw')}))),
    Rule('model-overload', 'no overload of a model class method matches',
         (MODEL_MEMBER,), _message(NO_MATCHING_MEMBER), _model_overload,
         _examples(
             ('  auto policy = qos.reliability();',
              "no matching member function for call to 'reliability'", 21,
              set()))),
    Rule('not-a-template', 'a name used with template arguments it lacks',
         (TEMPLATE_USE,), _message(NOT_A_TEMPLATE), _not_a_template,
         _examples(
             ('  auto e = map.elementsAs<Light>();',
              "'elementsAs' does not name a template but is followed by "
              'template arguments', 16, {(TEMPLATE_USE, 'elementsAs')}))),
    Rule('unknown-scope', 'a scope that is no class or namespace',
         (NAMESPACE, TYPE, TEMPLATE, FUNCTION, OBJECT),
         _message(NOT_A_SCOPE), _unknown_scope, _examples(
             ('  gen::Params p;',
              "'gen' is not a class, namespace, or enumeration", 3,
              {(NAMESPACE, 'gen')}))),
    Rule('undefined-macro-condition', 'a function-like macro in #if',
         (MACRO_CONDITION,), _message(UNDEFINED_MACRO), _undefined_macro,
         _examples(
             ('#if LIB_VERSION_GTE(2, 0, 0)',
              "function-like macro 'LIB_VERSION_GTE' is not defined", 5,
              {(MACRO_CONDITION, 'LIB_VERSION_GTE')}))),
    Rule('specialized-function', 'a specialisation of an unknown template',
         (SPECIALIZED,), _message(SPECIALIZATION), _specialization,
         _examples(
             ('template <> Id registerName(const Thing & t);',
              'no function template matches function template '
              "specialization 'registerName'", 16,
              {(SPECIALIZED, 'registerName')}))),
    Rule('base-class', 'an unknown base class', (TYPE, TEMPLATE),
         lambda seen: seen.message == 'expected class name', _base_class,
         _examples(
             ('class Label : public Widget', 'expected class name', 22,
              {(TYPE, 'Widget')}))),
    Rule('macro-with-body', 'an unknown macro followed by a body',
         (MACRO_FUNCTION,), _macro_with_body_applies, _macro_with_body,
         _examples(
             ('LIB_MODULE(name, m) {', 'expected unqualified-id', 1,
              {(MACRO_FUNCTION, 'LIB_MODULE')}))),
    Rule('macro-statement', 'an unknown macro at declaration level',
         (MACRO_VOID,), _macro_statement_applies, _macro_statement,
         _examples(
             ('LIB_REGISTER_POINT(Point, float, x, y)',
              'a type specifier is required for all declarations', 1,
              {(MACRO_VOID, 'LIB_REGISTER_POINT')}))),
    Rule('override-without-base', '`override` of no known virtual method',
         (NO_OVERRIDE,), _message(OVERRIDE), _no_override, _examples(
             ('  void paint() override;',
              "only virtual member functions can be marked 'override'", 15,
              {(NO_OVERRIDE, 'override')}))),
    Rule('literal-or-hash', 'a literal operator; a hash specialised twice',
         (LITERAL, NO_HASH), lambda seen: bool(
             LITERAL_OPERATOR.match(seen.message) or
             HASH_REDEFINED.match(seen.message)), _literal_or_hash,
         _examples(
             ('  auto a = "name"_arg = 1;',
              'no matching literal operator for call to '
              "'operator\"\"_arg' with arguments", 18,
              {(LITERAL, '_arg')}))),
    Rule('argument-not-value', 'a type where a value is expected',
         (MACRO_VALUE, VALUE), _message(ARGUMENT_NOT_VALUE),
         _argument_not_value, _examples(
             ('  ar & LIB_NVP(Base);',
              "'Base' does not refer to a value", 16,
              {(MACRO_VALUE, 'LIB_NVP')}))),
    Rule('macro-arguments-called', 'an unknown macro whose arguments call',
         (MACRO_VOID,), _macro_arguments_called_applies,
         _macro_arguments_called, _examples(
             ('  LIB_ON_EXIT((&a)(&b)) {',
              "called object type 'int *' is not a function or function "
              'pointer', 18, {(MACRO_VOID, 'LIB_ON_EXIT')}))),
    Rule('array-element-type', 'an unknown name as an array element type',
         (TYPE,), _array_element_applies, _array_element, _examples(
             ('  std::unique_ptr<info_t[]> infos;', 'expected expression',
              26, {(TYPE, 'info_t')}))),
    Rule('namespace-alias', 'an alias of an unknown namespace',
         (NAMESPACE,), lambda seen: seen.message.startswith(
             'expected namespace name'), _namespace_alias, _examples(
             ('namespace fs = lib::fs;', 'expected namespace name', 16,
              {(NAMESPACE, 'lib::fs')}))),
)


# the messages whose notes the rules read
NEEDS_NOTES = (NO_MATCHING_MEMBER,)


def needs_notes(message):
    """Whether a rule reads the notes of an error of this message."""
    return any(pattern.match(message) for pattern in NEEDS_NOTES)


def find_repairs(diagnostics, read_line, stand_in=None, texts=()):
    """{(kind, name): rule id}: what the rules make of these diagnostics.

    :param diagnostics: (message, file, line, column) of each error, or
      (message, file, line, column, notes) where its notes are needed
    """
    repairs = {}
    for message, file, line, column, *notes in diagnostics:
        text = read_line(file, line) if file else ''
        # the name the message is about, and the code that follows it
        quoted = QUOTED_NAME.search(message)
        subject = quoted.group(1) if quoted else None
        if file and subject:
            text, column = in_macro_arguments(
                read_line, file, line, text, column, subject)
        seen = Seen(
            message=message, file=file, line=line, column=column, text=text,
            subject=subject, read_line=read_line, texts=tuple(texts),
            stand_in=stand_in, after=after_name(text, column, subject) or
            next_line(read_line, file, line, text, subject),
            notes=tuple(notes[0]) if notes else ())
        for rule in RULES:
            if rule.applies(seen):
                for repair in rule.decide(seen):
                    repairs.setdefault(repair, rule.id)
                break
    return repairs


def repairs_from_diagnostics(diagnostics, read_line, texts=(),
                             declared=frozenset(), stand_in=None):
    """{(kind, qualified name)} that would fix these errors.

    See :func:`found_repairs`, which also says which rule made each.
    """
    return set(found_repairs(diagnostics, read_line, texts=texts,
                             declared=declared, stand_in=stand_in))


def found_repairs(diagnostics, read_line, texts=(), declared=frozenset(),
                  stand_in=None):
    """{(kind, qualified name): rule id} that would fix these errors.

    :param diagnostics: (message, file, line, column) of each error
    :param read_line: returns the text of (file, line), or ''
    :param texts: the code of the files with errors: a namespace declared
      here gets the names these use of it at once (clang reports those only
      once the namespace exists: one parse saved)
    :param declared: names the package's own code declares (see
      :func:`declared_names`): never declared again, their errors come
      from elsewhere
    :param stand_in: whether the unit's stand-ins hold a header (relative
      path): a member of a class of an unknown library's stand-in is
      declared with its class. None: the unit has no stand-ins, and a
      message named before its header is included is declared (otherwise
      its header is included, and written if no stand-in holds it yet)
    """
    aliases = aliases_of(texts)
    found = find_repairs(diagnostics, read_line, stand_in, texts)
    rule_of = {}
    for repair, rule in found.items():
        for renamed in unaliased({repair}, aliases):
            rule_of.setdefault(renamed, rule)
    for kind, name in list(rule_of):
        if kind == NAMESPACE and name not in declared:
            for used in uses_of_namespace(name, texts, aliases):
                rule_of.setdefault(used, USES_OF_NAMESPACE)
    kept = one_kind_each({
        r for r in rule_of
        if r[0] in INCLUDES or (
            (reopened_namespace(r) or not is_declared(r[1], declared)) and
            not any(part in KEYWORDS for part in r[1].split('::')))})
    result = {}
    for repair in kept:
        # (one_kind_each may rename a member into its class: its rule is
        # the rule that asked for the name)
        rule = rule_of.get(repair) or next(
            (rule_of[r] for r in rule_of if r[1].rsplit('::', 1)[-1] ==
             repair[1].rsplit('::', 1)[-1]), USES_OF_NAMESPACE)
        result.setdefault(included(repair, stand_in), rule)
    return result


# the rule id of the names a namespace's repair declares at once (what the
# code uses of the namespace)
USES_OF_NAMESPACE = 'uses-of-namespace'


def unknown_owner(match, stand_in):
    """The class a member repair goes into, if an unknown library's.

    An unknown-library header (rsia_model/unknown/<namespace>.h, see
    stubs.py) declared it without the member. Its repair hides that
    declaration (the header checks the repair's guard) and takes the
    members the unit uses. A class of the model or of the workspace is
    never declared again.
    """
    owner, arguments = match.group(2), match.group(3)
    if stand_in is None or '::' not in owner or not stand_in(
            os.path.join(UNKNOWN_DIR, owner.split('::')[0] + '.h')):
        return set()
    return {(TEMPLATE if arguments else TYPE, owner)}
