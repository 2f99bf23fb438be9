# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Parsing a C++ translation unit with libclang, and its parse errors."""

import clang.cindex as ci

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
