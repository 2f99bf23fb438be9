# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Parsing a C++ translation unit with libclang, and its parse errors."""

import ctypes
import re

import clang.cindex as ci
from colcon_rsia.frontend.cpp.cursors import overloaded_declarations

# incomplete: we never need the TU's template instantiations at its end
PARSE_OPTIONS = ci.TranslationUnit.PARSE_INCOMPLETE

# how many parse errors of one TU are kept in the summary
MAX_DIAGNOSTICS_PER_TU = 5


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


def errors_with_notes(tu, wanted):
    """(message, file, line, column, notes) of the errors `wanted` takes.

    The notes are the (message, file, line, column) of the error's notes
    that have a place (the overloads of an ambiguous call, the parameter
    an argument is passed to). Only errors whose message `wanted` accepts
    are read: a unit can have thousands of notes.
    """
    errors = []
    for diag in tu.diagnostics:
        if diag.severity >= ci.Diagnostic.Error and wanted(diag.spelling):
            loc = diag.location
            notes = [
                (note.spelling, note.location.file.name, note.location.line,
                 note.location.column)
                for note in diag.children if note.location.file]
            errors.append((diag.spelling, loc.file.name if loc.file else None,
                           loc.line, loc.column, notes))
    return errors


_FUNCTIONS = (ci.CursorKind.FUNCTION_DECL, ci.CursorKind.CXX_METHOD,
              ci.CursorKind.CONSTRUCTOR)


def parameter_types(tu, file, line, column, *, object_at=None):
    """The canonical parameter types of the function declared there.

    None when no function (a template, for one) is declared there, or its
    declaration is invalid (a parameter of an undeclared type reads `int`).

    :param object_at: (file, line, column) of the callee of a member call:
      a parameter that the template of the object's class spells with a
      name of its own (`const key_type &` of `std::map::erase`) is spelled
      as that member of the object's class (`const typename std::map<long,
      double>::key_type &`): the template's own spelling names nothing
      outside it
    """
    cursor = _cursor_at(tu, file, line, column)
    if (cursor is None or cursor.kind not in _FUNCTIONS) and object_at:
        # a declaration of the precompiled model, which clang does not find
        # by its place (`std::fmod` of <cmath>): among those the call names
        cursor = _overload_at(tu, object_at, file, line, column) or cursor
    if cursor is None or cursor.kind not in _FUNCTIONS or _invalid(cursor):
        return None
    types = []
    owner = None
    for argument in cursor.get_arguments():
        canonical = argument.type.get_canonical().spelling
        if _DEPENDENT in canonical and object_at is not None:
            member = _MEMBER_TYPE_SPELLING.match(argument.type.spelling)
            owner = owner or _object_type(tu, *object_at)
            if member is None or owner is None:
                return None
            canonical = (f'{member.group(1) or ""}typename '
                         f'{owner}::{member.group(2)}{member.group(3) or ""}')
        types.append(canonical)
    return types


# what canonical types of a class template's members show of its parameters
_DEPENDENT = 'type-parameter-'
# a parameter spelled with one name, as a class template's members name its
# types (`const_iterator`, `const key_type &`)
_MEMBER_TYPE_SPELLING = re.compile(r'^(const )?([A-Za-z_]\w*)( &{1,2})?$')


def _object_type(tu, file, line, column):
    """The canonical class of a member call's object, or None.

    Of the call whose callee is at (file, line, column): `m` of
    `m.erase(k)`, `*p` of `p->erase(k)`.
    """
    for cursor, children in _descent(tu, file, line, column):
        if cursor.kind == ci.CursorKind.MEMBER_REF_EXPR and children and \
                _spans(cursor, file, line, column) and \
                not _spans(children[0], file, line, column):
            spelling = children[0].type.get_canonical().spelling
            spelling = re.sub(r'^const |\s*(?:\*|&+)$', '', spelling)
            return spelling if spelling and _DEPENDENT not in spelling \
                and '<dependent' not in spelling else None
    return None


def _overload_at(tu, callee_at, file, line, column):
    """The function declared at (file, line, column) that a callee names.

    Of the overloaded name at callee_at, (file, line, column) of its call
    (an ambiguous call's callee refers to the set of them).
    """
    for cursor, _ in _descent(tu, *callee_at):
        overloaded = cursor.referenced if cursor.kind in (
            ci.CursorKind.DECL_REF_EXPR, ci.CursorKind.MEMBER_REF_EXPR) \
            else cursor
        if overloaded is None or \
                overloaded.kind != ci.CursorKind.OVERLOADED_DECL_REF:
            continue
        for declaration in overloaded_declarations(overloaded):
            place = declaration.location
            if place.file is not None and place.file.name == file and \
                    (place.line, place.column) == (line, column):
                return declaration
    return None


def parameter_type(tu, file, line, column):
    """The canonical type of the parameter declared there, or None."""
    cursor = _cursor_at(tu, file, line, column)
    if cursor is None or cursor.kind != ci.CursorKind.PARM_DECL or \
            _invalid(cursor):
        return None
    return cursor.type.get_canonical().spelling


def call_arguments(tu, file, line, column):
    """[(line, column, canonical type)] of the arguments of a call.

    Of the innermost call whose callee spans (file, line, column), also
    one that failed (clang keeps its callee and arguments); None if there
    is none.
    """
    found = None
    for cursor, children in _descent(tu, file, line, column):
        # (a failed call is an unexposed expression, as implicit casts
        # are, with the callee and the arguments)
        if (cursor.kind == ci.CursorKind.CALL_EXPR or len(children) > 1 and
                cursor.kind == ci.CursorKind.UNEXPOSED_EXPR) and \
                _spans(children[0], file, line, column):
            found = children[1:]
    if found is None:
        return None
    return [(argument.extent.start.line, argument.extent.start.column,
             argument.type.get_canonical().spelling) for argument in found]


def _descent(tu, file, line, column):
    """(cursor, its children) from the unit down to (file, line, column).

    Each step goes to the first child that spans the place; the last is the
    innermost cursor there.
    """
    cursor = tu.cursor
    while cursor is not None:
        children = list(cursor.get_children())
        yield cursor, children
        cursor = next((child for child in children
                       if _spans(child, file, line, column)), None)


def _spans(cursor, file, line, column):
    start, end = cursor.extent.start, cursor.extent.end
    return start.file is not None and start.file.name == file and \
        (start.line, start.column) <= (line, column) <= (end.line, end.column)


def _cursor_at(tu, file, line, column):
    return ci.Cursor.from_location(tu, tu.get_location(file, (line, column)))


def _invalid(cursor):
    """Whether clang found the declaration invalid (cindex lacks the call)."""
    global _is_invalid_declaration
    if _is_invalid_declaration is None:
        function = ci.conf.lib.clang_isInvalidDeclaration
        function.argtypes = [ci.Cursor]
        function.restype = ctypes.c_uint
        _is_invalid_declaration = function
    return bool(_is_invalid_declaration(cursor))


_is_invalid_declaration = None
