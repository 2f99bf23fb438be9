# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Edits of the package's code, in memory, for errors no declaration fixes.

Some errors of the model's parse come from its catch-all types themselves,
where C++ asks for one exact type:

- a lambda without a declared result whose returns give a catch-all
  (``rsia_model::Any``) in one branch and a ``double`` in another;
- ``auto *p = image.ptr<T>(row)``, where the catch-all is no pointer;
- ``constexpr double v = deg2rad(40.0)``, where the repaired function
  cannot be constant;
- ``const auto & [id, path] = any``, where the catch-all decomposes into no
  names;
- ``f(&msg.indices)`` for a ``std::vector<int> *``, where the address of a
  catch-all is an ``rsia_model::Any *``;
- ``cond ? "" : any + "/"``, ``cond ? any : nullptr``, where an operand
  and a catch-all have no common type, or ``cond ? level : Status::OK``,
  where each converts to the other;
- ``getRPY(pose.orientation)``, ``starts.erase(lane.id())``,
  ``std::vector<int>(indices->indices)``, where a catch-all converts to the
  parameter of every overload alike and the call is ambiguous;
- ``correct(params_.get())`` for a ``const Params &``, a class of the
  package that no catch-all converts to, and assignments of the classes a
  repair declared to real ones (``obstacles = constraints.polygons``);
- ``pushUniqueVector(lanes, any)`` for ``(T &, const T &)``, where the
  catch-all deduces another ``T``;
- ``return new ceres::AutoDiffLocalParameterization<...>;`` for a
  ``ceres::LocalParameterization *``, where the repaired classes know no
  base classes;
- ``for (lanelet::LineString3d & line : map->lineStringLayer)``, where an
  element of a catch-all binds no reference to a class;
- ``dynamic_cast<nvinfer1::IConvolutionLayer *>(layer)``, where a repaired
  class has no virtual functions, and ``reinterpret_cast<const float *>(
  any)``, where a catch-all is no pointer.

The real build has the real types and none of these errors. So the unit is
parsed again with the line edited in memory (libclang's unsaved files,
never on disk): the lambda returns an ``rsia_model::AnyValue``, the
``auto *`` becomes an ``auto``, the ``constexpr`` a ``static const`` (a
lambda uses it uncaptured, as it would the constant), the binding's
initializer becomes a value of as many names (see message.h's ``Bound``),
the ``&`` goes (the catch-all converts to any pointer; a range-for's
variable is a copy), the operand of a
conditional becomes a ``std::string`` (a literal) or a catch-all value
(``nullptr``, a number), the arguments of
the ambiguous call are made the parameters of its first candidate that
is no template, spelled as clang spells them canonically so that any
scope can name them, or, for a member of a class template, as members of
the object's class (``typename std::map<long, double>::const_iterator``;
the real build may take another overload; the call and its arguments are
there for the facts either way), the one argument of an ambiguous
constructor or functional cast becomes the class constructed, an argument
passed to a class parameter becomes ``rsia_model::as<Params>(arg)`` (so
does one beside a real argument of a template, with that argument's type,
and a pointer where the code names the pointer wanted), the value
assigned ``rsia_model::assigned_as<decltype(target)>(value)``, the
``dynamic_cast`` a ``reinterpret_cast``, and that of a catch-all an
``rsia_model::as``. An edit never
adds or removes a line break, so every fact keeps its file and line.

An edit is kept among the unit's repairs like a declaration, as
``(kind, "file:line:column")`` with the position in the file as it is on
disk, and checked against the file's text each time it is applied: when
the file changed, an edit whose text is no longer there is dropped.
"""

import re
from urllib.parse import quote

from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import address_of
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import arguments_of_call
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import binding_names
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import constexpr_keyword
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import end_before
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import end_of_argument
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import lambda_body
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import masked_reader
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import offset_of
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import operands
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import pointer_star
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import position_of
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import range_reference
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import statement_start
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import word_before

# the kinds of edit, as repair headers name them
LAMBDA_RESULT = 'edit-lambda-result'  # `-> AnyValue` before a lambda's body
AUTO_POINTER = 'edit-auto-pointer'    # the `*` of `auto *p` blanked
CONSTEXPR = 'edit-constexpr'          # `constexpr` made `const`
BINDING = 'edit-binding'              # `[a, b] = Bound<2>() <<= any`
ADDRESS = 'edit-address'              # the `&` of `&any` blanked
# `c ? as<::std::string>("") : any`: an operand of a conditional made a
# type, at the `?`; which operand and the type in the kind
# (`edit-operand:3:<T>`, quoted)
OPERAND = 'edit-operand'
# `f(as<T>(a))`: a call's arguments made the types of one overload's
# parameters, their types in the kind (`edit-cast:<T1>;<T2>`, quoted)
CAST = 'edit-cast'
# `as<T>(a)`: a value made the class it must be (its parameter's, its
# variable's, its function's result), the class in the kind
# (`edit-as:<T>`, quoted)
AS = 'edit-as'
# `target = assigned_as<decltype(target)>(value)`, at the `=`
ASSIGNED = 'edit-assigned'
# `dynamic_cast` made `reinterpret_cast`, at the keyword
DYNAMIC_CAST = 'edit-dynamic-cast'
# `reinterpret_cast` (of a catch-all) made `::rsia_model::as`, at the keyword
REINTERPRET_CAST = 'edit-reinterpret-cast'
# the `&` of a range-for's `T & x : any` blanked (a copy of each element)
RANGE_REFERENCE = 'edit-range-reference'
# a subscript's index made a number (`data[any + n]` of a pointer), at `[`
INDEX = 'edit-index'
# `(object.*member)(...)` of a repaired class's member, a catch-all's
# address: `(*member)(...)`, at the `.*` or `->*`
MEMBER_POINTER = 'edit-member-pointer'
EDIT_KINDS = (LAMBDA_RESULT, AUTO_POINTER, CONSTEXPR, BINDING, ADDRESS,
              OPERAND, CAST, AS, ASSIGNED, DYNAMIC_CAST, REINTERPRET_CAST,
              RANGE_REFERENCE, INDEX, MEMBER_POINTER)

# a type in a message, with what its alias names: 'value_type' (aka 'double')
_TYPE = r"'.*'(?: \(aka '.*'\))?"
_LAMBDA_RESULT_ERROR = re.compile(
    f'^return type {_TYPE} must match previous return type {_TYPE} '
    'when lambda expression has unspecified explicit return type$')
_AUTO_POINTER_ERROR = re.compile(
    r"^variable '\w+' with type '(?:const )?auto \*(?: ?const)?' has "
    r"incompatible initializer of type '(?:::)?rsia_model::\w+'$")
_CONSTEXPR_ERROR = re.compile(
    r"^constexpr variable '\w+' must be initialized by a constant "
    r'expression$|^constexpr variable cannot have non-literal type ')
_BINDING_ERROR = re.compile(
    r"^type '.*' decomposes into \d+ elements?, but \d+ names were "
    r'provided$|^cannot decompose ')
# a catch-all's type as messages spell it (`const ::rsia_model::AnyElement`)
_ANY = r'(?:const )?(?:(?:::)?rsia_model::)?Any(?:Element|Value)?'
_ADDRESS_ERROR = re.compile(
    r"^cannot initialize a (?:parameter|variable) of type '.*\*'"
    r"(?: \(aka '.*'\))? with an rvalue of type "
    r"'(?:::)?(?:rsia_model::)?Any \*'$")
# a pointer's subscript by a catch-all, which converts to every number
_INDEX_ERROR = re.compile(r'^array subscript is not an integer$')
# a member pointer that is a catch-all's address
_MEMBER_POINTER_ERROR = re.compile(
    r'^right hand operand to (?:\.|->)\* has non-pointer-to-member type '
    rf"'{_ANY} \*'$")
# an element of a catch-all, which binds no reference to a class of an
# unknown library (`for (lanelet::LineString3d & line : map->lineStringLayer)`)
_ELEMENT_CONVERSION_ERROR = re.compile(
    r"^no viable conversion from '(?:const )?(?:(?:::)?rsia_model::)?"
    r"AnyElement' to '.*'$")
# a class a repair declared has no virtual functions, which dynamic_cast
# asks of its operand's
_NOT_POLYMORPHIC_ERROR = re.compile(r"^'.*' is not polymorphic$")
# and a catch-all is no pointer or number to reinterpret
_REINTERPRET_ERROR = re.compile(
    rf"^reinterpret_cast from '{_ANY}' to '.*' is not allowed$")
# a pointer to a class a repair declared where the real class derives from
# the one wanted (`return new ceres::AutoDiffLocalParameterization<...>;`
# for a `ceres::LocalParameterization *`)
# (the pointer wanted may have an alias: `pointer` of a std::unique_ptr's
# reset, aka 'nvinfer1::IInt8Calibrator *')
_POINTER_MISMATCH = re.compile(
    r'^cannot initialize (return object|a variable|a parameter) of type '
    r"'([^']*)'(?: \(aka '([^']*)'\))? with an [lr]value of type "
    r"'[^']*\*'(?: \(aka '[^']*'\))?$")
# the errors of a conditional's operands (a literal's type is an array:
# `const char[1]` of "")
LITERAL_OPERAND_ERROR = re.compile(
    r"^incompatible operand types \((?:'(const char\[\d+\])' and .*|"
    r".* and '(const char\[\d+\])')\)$")
NULL_OPERAND_ERROR = re.compile(
    r"^non-pointer operand type '(?:const )?Any(?:Element|Value)?' "
    'incompatible with nullptr$')
# (a catch-all beside a class the code names: `ok ? goal.value() : make()`)
OTHER_OPERAND_ERROR = re.compile(
    rf'^incompatible operand types \(({_TYPE}) and ({_TYPE})\)$')
MUTUAL_OPERAND_ERROR = re.compile(
    rf'^conditional expression is ambiguous; ({_TYPE}) can be converted to '
    rf'({_TYPE}) and vice versa$')
STRING = '::std::string'
# the same, for an operand that is no literal (an edit checks that the
# operand it makes a `STRING` is still a literal)
CONSTANT_STRING = '::std::basic_string<char>'
STRING_TYPE = re.compile(
    r'^(?:const )?(?:std::)?(?:string|basic_string<char>)$')
CATCH_ALL_VALUE = '::rsia_model::AnyValue'
# from a catch-all, or from a class a repair or stand-in declared (the
# real build converts it, or it would not build); the class as the message
# spells it: where the code names it
_NO_CONVERSION = re.compile(
    r"^no viable conversion from (?:returned value of type )?'[^']*'"
    r"(?: \(aka '[^']*'\))? to (?:function return type )?'([^']*)'"
    r"(?: \(aka '[^']*'\))?$")
# a C string: the one pointer a catch-all does not convert to (message.h)
_C_STRING = re.compile(r'^(?:const )?char \*$')
_NO_MATCH = re.compile(
    r"^no matching (?:member )?function for call to '.*'$|"
    r"^no matching function for call to object of type '.*'$|"
    r'^no matching constructor for initialization of ')
# a candidate's note that names the argument the model's types cannot
# make the parameter's
_NOT_CONVERTED = re.compile(
    r'^candidate (?:function|constructor) not viable: no known conversion '
    r"from '([^']*)'(?: \(aka '[^']*'\))? to '([^']*)'(?: \(aka '([^']*)'\))? "
    r'for (\d+)(?:st|nd|rd|th) argument')
# (from a message's string constant, an int in the model, to a string)
_CONSTANT_FOR_STRING = re.compile(
    r'^candidate constructor not viable: no known conversion from '
    r"'const int' to 'const (?:std::)?(?:basic_string<char>|string)'")
# a template whose parameter a catch-all argument deduces as well as a real
# one (`pushUniqueVector(lanes, any)` for `(T &, const T &)`)
_CONFLICTING = re.compile(
    r'^candidate template ignored: deduced conflicting types for parameter '
    r"'\w+' \('(.*?)'(?: \(aka '(.*?)'\))? vs\. '(.*?)'(?: \(aka '(.*?)'\))?\)$")
# the address of a catch-all
_CATCH_ALL_POINTER = re.compile(rf'^{_ANY} \*$')
# a catch-all's type, canonically spelled
_CATCH_ALL = re.compile(rf'^{_ANY}(?: ?&+)?$')
_NO_ASSIGNMENT = re.compile(r"^no viable overloaded '='$")
# (at the value assigned: `*log = any` for a `const char *`)
# (or a pointer to a class of an unknown library to its real base's:
# `loss_ = new ceres::HuberLoss(0.7)` for a `ceres::LossFunction *`)
_NOT_ASSIGNABLE = re.compile(
    rf"^assigning to '.*' from incompatible type '{_ANY}'$|"
    r"^incompatible pointer types assigning to '[^']*\*'"
    r"(?: \(aka '[^']*'\))? from '[^']*\*'(?: \(aka '[^']*'\))?$")
# what an assignment's target may be: a name, members, subscripts, getters
# (also with simple arguments: `std::tie(left, right)`)
_TARGET = re.compile(
    r'^\*?\s*[A-Za-z_]\w*(?:\s*(?:\.|->|::)\s*[A-Za-z_]\w*|'
    r'\s*\[[^\[\];]*\]|\s*\([^;()]*\))*$')
_AMBIGUOUS_CALL = re.compile(
    r"^call to (?:member function |constructor of )?'.*'"
    r"(?: \(aka '.*'\))? is ambiguous$")
_AMBIGUOUS_CONSTRUCTOR = re.compile(
    r"^call to constructor of '([^']*)'(?: \(aka '[^']*'\))? is ambiguous$|"
    rf"^ambiguous conversion for functional-style cast from '{_ANY}' to "
    r"'([^']*)'(?: \(aka '[^']*'\))?$")
# the types of C++ itself, which a catch-all converts to
BUILTIN = re.compile(
    r'^(?:(?:un)?signed\s+|long\s+|short\s+)*'
    r'(?:int|long|short|char|bool|float|double|void|size_t)?$')
# what a canonical type spelling can hold that no scope can name
UNNAMEABLE = re.compile(r'\(anonymous|\(lambda|\(unnamed|type-parameter|::\(')
# a variable's name up to its initializer (`screen = ` of `Screen *screen =
# DefaultScreenOfDisplay(d)`, where clang reports the conversion)
DECLARATOR = re.compile(r'[A-Za-z_]\w*\s*=(?!=)\s*')

# a class that is moved, never copied
MOVE_ONLY = re.compile(r'^(?:::)?std::unique_ptr<')
RESULT = '-> ::rsia_model::AnyValue '
# the keyword each edit of a cast replaces, and with what
CAST_KEYWORDS = {DYNAMIC_CAST: ('dynamic_cast', 'reinterpret_cast'),
                 REINTERPRET_CAST: ('reinterpret_cast', '::rsia_model::as')}
# words that begin statements, never an assignment's target
KEYWORDS = frozenset(('return', 'if', 'else', 'case', 'throw', 'delete',
                      'co_return', 'goto'))


def edits_from_diagnostics(diagnostics, read_code):
    """{(kind, "file:line:column")}: the edits that would fix these errors.

    :param diagnostics: (message, file, line, column) of the errors in the
      workspace's files, their columns on disk (see :func:`disk_column`)
    :param read_code: returns a file's text on disk, read as latin-1 (one
      character per byte, as clang counts columns), or None
    """
    edits = set()
    masked_of = masked_reader(read_code)
    for message, file, line, column in diagnostics:
        kind = _kind_of(message)
        pointer = _POINTER_MISMATCH.match(message)
        if pointer and file and ' ' not in file and \
                not _ADDRESS_ERROR.match(message):
            edits |= _as_pointer(masked_of(file), file, line, column, pointer)
            continue
        if kind is None or not file or ' ' in file:
            continue  # (a repair header's entry is one word)
        masked = masked_of(file)
        offset = None if masked is None else offset_of(masked, line, column)
        if offset is None:
            continue
        if kind == OPERAND:
            edits |= operand_edit(masked, file, offset, message)
            continue
        anchor = ANCHORS[kind](masked, offset)
        if anchor is not None:
            at_line, at_column = position_of(masked, anchor)
            edits.add((kind, f'{file}:{at_line}:{at_column}'))
    return edits


def is_edit(kind):
    """Whether a repair's kind is one of these edits."""
    return kind.partition(':')[0] in EDIT_KINDS


def needs_notes(message):
    """Whether :func:`edits_from_notes` reads an error of this message."""
    return any(pattern.match(message) for pattern in (
        _AMBIGUOUS_CALL, _AMBIGUOUS_CONSTRUCTOR, _NO_CONVERSION, _NO_MATCH,
        _NO_ASSIGNMENT, _NOT_ASSIGNABLE))


def edits_from_notes(errors, read_code, *, parameter_types,
                     parameter_type, call_arguments=lambda *at: None):
    """{(kind, "file:line:column")}: the edits that need declarations.

    Casts that settle ambiguous calls; arguments, initializers and returned
    values made the class they must be; values assigned made the type of
    their target.

    :param errors: (message, file, line, column, notes) of the errors,
      columns on disk, with the (message, file, line, column) of clang's
      notes
    :param read_code: as for :func:`edits_from_diagnostics`
    :param parameter_types: returns the parameter types of the function
      declared at a (file, line, column), spelled canonically; None for a
      template or anything else
    :param parameter_type: the same, of the parameter declared there
    :param call_arguments: returns [(line, column, canonical type)] of the
      arguments of the call whose callee is at (file, line, column), on
      disk; None if there is none
    """
    edits = set()
    masked_of = masked_reader(read_code)
    for message, file, line, column, notes in errors:
        if not file or ' ' in file:
            continue
        if _AMBIGUOUS_CALL.match(message) or \
                _AMBIGUOUS_CONSTRUCTOR.match(message):
            for note, *candidate in notes:
                types = parameter_types(
                    *candidate, callee=(file, line, column)) \
                    if note.startswith('candidate') else None
                if types and not any(UNNAMEABLE.search(t) for t in types):
                    joined = quote(';'.join(types), safe='')
                    edits.add((f'{CAST}:{joined}', f'{file}:{line}:{column}'))
                    break
            else:
                constructed = _AMBIGUOUS_CONSTRUCTOR.match(message)
                masked = masked_of(file)
                if constructed and masked is not None:
                    # no candidate to name (a class template's): a single
                    # argument is made the class itself, as copied
                    offset = offset_of(masked, line, column)
                    arguments = None if offset is None else \
                        arguments_of_call(masked, offset)
                    if arguments is not None and len(arguments) == 1:
                        edits |= _as_parameter_of_argument(
                            masked, file, line, column, 0,
                            _named_in(masked, constructed.group(1) or
                                      constructed.group(2)))
        elif _NO_CONVERSION.match(message):
            # at the argument, its parameter in a note (spelled so that any
            # scope names it); at a returned value, or at the variable an
            # initializer initialises, the class as the code names it there
            parameter = next((parameter_type(*at) for note, *at in notes
                              if note.startswith('passing argument to')),
                             None)
            masked = masked_of(file)
            offset = None if masked is None else offset_of(masked, line, column)
            if offset is not None and range_reference(masked, offset):
                continue  # (a range-for's variable: its own edit)
            if parameter is None and masked is not None:
                wanted = _NO_CONVERSION.match(message).group(1)
                parameter = wanted if _C_STRING.match(wanted) else \
                    _named_in(masked, wanted)
                if 'returned value' not in message:
                    line, column = _initializer_of(masked, line, column)
            if _after_new(masked, line, column):
                # `new Handle(any)`, at the class: the argument becomes one
                edits |= _as_parameter_of_argument(
                    masked, file, line, column, 0, parameter)
            else:
                edits |= _as_parameter(masked, file, line, column, parameter)
        elif _NO_MATCH.match(message):
            # at the callee; the argument in a candidate's note
            for note, *candidate in notes:
                match = _NOT_CONVERTED.match(note)
                types = parameter_types(*candidate) if match else None
                index = int(match.group(4)) - 1 if match else 0
                made = _as_parameter_of_argument(
                    masked_of(file), file, line, column, index,
                    types[index]) if types and index < len(types) else None
                if made:  # (else the next candidate may name it)
                    edits |= made
                    break
                if match and _CATCH_ALL_POINTER.match(match.group(1)):
                    # `push_back(&msg.paths.at(i))` for a `const Path *`:
                    # the catch-all itself converts to any pointer
                    made = _address_argument(
                        masked_of(file), file, line, column, index)
                    if made:
                        edits |= made
                        break
                if match and masked_of(file) is not None and (
                        _CATCH_ALL.match(match.group(1)) or
                        _CONSTANT_FOR_STRING.match(note)):
                    # no declaration to read (a lambda's parameters, a
                    # class template's): the class as the note spells it,
                    # where the code names it; a string for a message's
                    # constant (an int in the model); a C string also
                    # through an alias (`const value_type` aka 'char
                    # *const' of a vector's push_back)
                    real = re.sub(r'\s*\bconst$', '',
                                  match.group(3) or match.group(2))
                    named = STRING if _CONSTANT_FOR_STRING.match(note) \
                        else real if _C_STRING.match(real) \
                        else _named_in(masked_of(file), match.group(2))
                    if named:
                        edits |= _as_parameter_of_argument(
                            masked_of(file), file, line, column, index,
                            named)
                        break
                match = _CONFLICTING.match(note)
                if match:
                    edits |= _as_deduced(
                        masked_of(file), file, match,
                        call_arguments(file, line, column))
                    break
        elif _NO_ASSIGNMENT.match(message) or \
                _NOT_ASSIGNABLE.match(message):
            masked = masked_of(file)
            offset = None if masked is None else offset_of(masked, line, column)
            if offset is not None and masked[offset] != '=':
                offset = end_before(masked, offset) - 1  # the value's `=`
            if offset is not None and _assignment(masked, offset):
                at_line, at_column = position_of(masked, offset)
                edits.add((ASSIGNED, f'{file}:{at_line}:{at_column}'))
    return edits


def _assignment(masked, equals):
    """(target, value start, value end) of the assignment at its `=`."""
    if masked[equals] != '=' or masked[equals + 1:equals + 2] == '=' or \
            masked[equals - 1:equals] in '=!<>+-*/%&|^':
        return None
    start = statement_start(masked, equals)
    target = ' '.join(masked[start:equals].split())
    if not _TARGET.match(target) or target.split()[0] in KEYWORDS:
        return None
    value = equals + 1
    while value < len(masked) and masked[value].isspace():
        value += 1
    end = None if masked[value:value + 1] == '{' else \
        end_of_argument(masked, value)
    return None if end is None else (target, value, end)


def _as_pointer(masked, file, line, column, mismatch):
    """The edit that makes a pointer the pointer type a message wants.

    The type as the message spells it, if the code names it so (see
    :func:`_named_in`); at a variable, its initializer.
    """
    if masked is None:
        return set()
    wanted = next((_named_in(masked, spelled)
                   for spelled in mismatch.group(2, 3)
                   if spelled and spelled.endswith('*') and
                   _named_in(masked, spelled)), None)
    if mismatch.group(1) == 'a variable':
        line, column = _initializer_of(masked, line, column)
    return _as_parameter(masked, file, line, column, wanted)


def _after_new(masked, line, column):
    """Whether the code at (line, column) follows a `new`."""
    offset = None if masked is None else offset_of(masked, line, column)
    return offset is not None and word_before(masked, offset) == 'new'


def _named_in(masked, spelled):
    """A type as a message spells it, if the code names it so; else None.

    Clang spells a type as the code wrote it, but drops some scopes
    (`shared_ptr<T>` for `std::shared_ptr<T>`), and an undeclared type
    reads `int`: a class the file does not name as spelled is no edit's.
    """
    core = re.sub(r'^const\s+|[\s*&]+$', '', spelled)
    if not core or BUILTIN.match(core):
        return None
    pattern = r'(?<![\w:])' + r'\s*'.join(
        re.escape(part) for part in re.findall(r'\w+|\S', core))
    return spelled if re.search(pattern, masked) else None


def _initializer_of(masked, line, column):
    """Where the initializer of the variable at (line, column) begins."""
    offset = offset_of(masked, line, column)
    declarator = None if offset is None else \
        DECLARATOR.match(masked, offset)
    return (line, column) if declarator is None else \
        position_of(masked, declarator.end())


def _as_parameter(masked, file, line, column, parameter):
    """The edit that makes the value at a position a `parameter`."""
    if masked is None or not parameter or UNNAMEABLE.search(parameter):
        return set()
    offset = offset_of(masked, line, column)
    if offset is None or end_of_argument(masked, offset) is None:
        return set()
    target = re.sub(r'\s*&+$', '', parameter)
    return {(f'{AS}:{quote(target, safe="")}', f'{file}:{line}:{column}')}


def _as_parameter_of_argument(masked, file, line, column, index,
                              parameter):
    """The same for the index-th argument of the call at a position."""
    if masked is None:
        return set()
    callee = offset_of(masked, line, column)
    arguments = None if callee is None else arguments_of_call(masked, callee)
    if not arguments or index >= len(arguments):
        return set()
    at_line, at_column = position_of(masked, arguments[index][0])
    return _as_parameter(masked, file, at_line, at_column, parameter)


def _address_argument(masked, file, line, column, index):
    """The edit that drops the `&` of the index-th argument of a call."""
    callee = None if masked is None else offset_of(masked, line, column)
    arguments = None if callee is None else arguments_of_call(masked, callee)
    if not arguments or index >= len(arguments):
        return set()
    start = arguments[index][0]
    if address_of(masked, start) != start:
        return set()
    at_line, at_column = position_of(masked, start)
    return {(ADDRESS, f'{file}:{at_line}:{at_column}')}


def _as_deduced(masked, file, conflict, arguments):
    """The edits that settle a template parameter deduced two ways.

    One way is a catch-all: the catch-all arguments are made the real
    type, the canonical one of the argument clang deduced it from (the
    note drops its scopes), found by the spelling the note gives. But a
    number beside a message field's own catch-all (`AnyValue`: `V` of a
    `std::unordered_map<K, V>` of message fields) is a message's constant
    (an int in the model): the number is made the field's. Both ways
    catch-alls: a field's own wins over a plain one (`Any`).
    """
    if masked is None or not arguments:
        return set()
    spellings = [_unscoped(conflict.group(2) or conflict.group(1)),
                 _unscoped(conflict.group(4) or conflict.group(3))]
    real = [t for t in spellings if not _CATCH_ALL.match(t)]
    if len(real) == 2:
        return set()

    def made(of_type, wanted):
        return set().union(*(
            _as_parameter(masked, file, at_line, at_column, wanted)
            for at_line, at_column, argument_type in arguments
            if of_type(argument_type)))
    if not real:
        own = set(spellings) - {'Any'}
        return made(lambda t: _unscoped(t) == 'Any',
                    f'::rsia_model::{own.pop()}') if len(own) == 1 else set()
    catch_all = next(t for t in spellings if t != real[0])
    if catch_all != 'Any' and BUILTIN.match(real[0]):
        return made(lambda t: _unscoped(t) == real[0],
                    f'::rsia_model::{catch_all}')
    deduced = next((re.sub(r'^const |\s*&+$', '', t)
                    for _, _, t in arguments
                    if _unscoped(t) == real[0]), None)
    return set() if deduced is None else made(_CATCH_ALL.match, deduced)


def _unscoped(spelled):
    """A type's spelling without `const`, references and scopes."""
    return re.sub(r'\b\w+::|^const |\s*&+$', '', spelled)


def _kind_of(message):
    for kind, pattern in ((LAMBDA_RESULT, _LAMBDA_RESULT_ERROR),
                          (AUTO_POINTER, _AUTO_POINTER_ERROR),
                          (CONSTEXPR, _CONSTEXPR_ERROR),
                          (BINDING, _BINDING_ERROR),
                          (ADDRESS, _ADDRESS_ERROR),
                          (DYNAMIC_CAST, _NOT_POLYMORPHIC_ERROR),
                          (REINTERPRET_CAST, _REINTERPRET_ERROR),
                          (RANGE_REFERENCE, _ELEMENT_CONVERSION_ERROR),
                          (INDEX, _INDEX_ERROR),
                          (MEMBER_POINTER, _MEMBER_POINTER_ERROR),
                          (OPERAND, LITERAL_OPERAND_ERROR),
                          (OPERAND, NULL_OPERAND_ERROR),
                          (OPERAND, OTHER_OPERAND_ERROR),
                          (OPERAND, MUTUAL_OPERAND_ERROR)):
        if pattern.match(message):
            return kind
    return None


def operand_edit(masked, file, question, message):
    """The edit that gives one operand of the conditional at `?` a type.

    A literal beside a catch-all becomes a std::string, and so does an int
    (a message's constant, in the model) beside a string; a `nullptr` beside
    one, and a value each converts to (`level` and `Status::OK`), becomes a
    catch-all value; a catch-all beside a class the code names becomes
    that class. The literal is the operand that is only white space once
    literals are masked (adjacent literals too); it is wrapped whole.
    """
    spans = operands(masked, question)
    if spans is None:
        return set()
    texts = [masked[start:end].strip() for start, end in spans]
    which = type_name = None
    literal = LITERAL_OPERAND_ERROR.match(message)
    mutual = MUTUAL_OPERAND_ERROR.match(message)
    other = OTHER_OPERAND_ERROR.match(message)
    if literal and (literal.group(1) or literal.group(2)):
        which, type_name = (2 if literal.group(1) else 3), STRING
        if texts[which - 2]:
            return set()
    elif NULL_OPERAND_ERROR.match(message) and 'nullptr' in texts:
        which, type_name = texts.index('nullptr') + 2, CATCH_ALL_VALUE
    elif mutual:
        catch_alls = [bool(_CATCH_ALL.match(aliased(t)))
                      for t in mutual.groups()]
        if catch_alls in ([True, False], [False, True]):
            # the other operand becomes the catch-all's
            which, type_name = 3 if catch_alls[0] else 2, CATCH_ALL_VALUE
    elif other:
        types = other.groups()
        catch_alls = [bool(_CATCH_ALL.match(aliased(t))) for t in types]
        constants = [bool(re.match(r'^(?:const )?int$', aliased(t)))
                     for t in types]
        strings = [bool(STRING_TYPE.match(aliased(t))) for t in types]
        if constants in ([True, False], [False, True]) and any(strings):
            # a message's string constant, an int in the model, beside a
            # string (`stopped ? Scenario::PARKING : current`): the real
            # code has two strings
            which, type_name = (2 if constants[0] else 3), CONSTANT_STRING
        elif catch_alls in ([True, False], [False, True]):
            # the catch-all becomes the other's class, as the code names it
            which = 2 if catch_alls[0] else 3
            spelled = re.match(r"^'(.*?)'", types[3 - which]).group(1)
            type_name = _named_in(masked, re.sub(r'^const ', '', spelled))
    if which is None or type_name is None:
        return set()
    at_line, at_column = position_of(masked, question)
    return {(f'{OPERAND}:{which}:{quote(type_name, safe="")}',
             f'{file}:{at_line}:{at_column}')}


def aliased(spelled):
    """What a message's type names: its aka's type, or its own."""
    match = re.match(r"^'(.*?)'(?: \(aka '(.*)'\))?$", spelled)
    return (match.group(2) or match.group(1)) if match else spelled


def cast_keyword(kind):
    """The anchor of an edit of a cast: the keyword at or before offset."""
    keyword = CAST_KEYWORDS[kind][0]
    pattern = re.compile(rf'\b{keyword}\b')

    def anchor(masked, offset):
        found = list(pattern.finditer(
            masked, statement_start(masked, offset),
            offset + len(keyword)))
        return found[-1].start() if found else None
    return anchor


# where each edit is anchored, from the place clang reports its error
ANCHORS = {
    LAMBDA_RESULT: lambda_body,
    AUTO_POINTER: pointer_star,
    CONSTEXPR: constexpr_keyword,
    BINDING: binding_names,
    ADDRESS: address_of,
    RANGE_REFERENCE: range_reference,
    INDEX: lambda masked, offset: offset if masked[offset] == '[' else None,
    MEMBER_POINTER: lambda masked, offset: offset if masked.startswith(
        ('.*', '->*'), offset) else None,
    DYNAMIC_CAST: cast_keyword(DYNAMIC_CAST),
    REINTERPRET_CAST: cast_keyword(REINTERPRET_CAST),
}
