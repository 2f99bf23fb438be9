# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""One unit parsed, and repaired while repairing pays."""

from dataclasses import dataclass
from dataclasses import field
import os
import threading
from typing import Optional

from colcon_rsia import safe_files
from colcon_rsia.frontend.cpp.model_mode.headers import MODEL_HEADERS_DIR
from colcon_rsia.frontend.cpp.model_mode.model_index import declared_names
from colcon_rsia.frontend.cpp.model_mode.recovery import applied
from colcon_rsia.frontend.cpp.model_mode.recovery import edits
from colcon_rsia.frontend.cpp.model_mode.recovery import messages
from colcon_rsia.frontend.cpp.model_mode.recovery import overlay
from colcon_rsia.frontend.cpp.model_mode.recovery import render
from colcon_rsia.frontend.cpp.model_mode.recovery import store
from colcon_rsia.frontend.cpp.model_mode.recovery.declared import \
    file_declarations
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import HEADER
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import is_edit
from colcon_rsia.frontend.cpp.model_mode.recovery.rules import found_repairs
from colcon_rsia.frontend.cpp.model_mode.recovery.rules import needs_notes
# (the parse's diagnostics and the declarations they point at; never the walk)
from colcon_rsia.frontend.cpp.parse import call_arguments
from colcon_rsia.frontend.cpp.parse import error_diagnostics
from colcon_rsia.frontend.cpp.parse import errors_with_notes
from colcon_rsia.frontend.cpp.parse import parameter_type
from colcon_rsia.frontend.cpp.parse import parameter_types

# parses of a unit after the first: each round fixes what the previous one
# revealed (a namespace, then the names used in it, then an edit of a call
# the names made ambiguous, then the assignment of its result)
MAX_REPAIR_ROUNDS = 4

# the source files whose declarations a unit never repairs
CXX_FILES = ('.cpp', '.cc', '.cxx', '.c++', '.C', '.h', '.hh', '.hpp',
             '.hxx', '.h++', '.ipp')
SKIPPED_DIRECTORIES = frozenset({
    'test', 'tests', 'build', 'install', 'devel', 'log', 'CMakeFiles'})


@dataclass
class ParsedUnit:
    """What :func:`parse_unit` made of a unit."""

    tu: object
    facts: object = None         # the walk's facts of `tu`, when asked for
    rounds: int = 0              # parses after the first
    # {(kind, name): rule id}: the unit's repairs (see store.py)
    repairs: dict = field(default_factory=dict)
    # the calls the kept parse lost, when the rounds counted them
    # (`unrecorded` given); None otherwise
    lost_calls: Optional[int] = None


def parse_unit(index, entry, *, parse, resource_dir, package_path, relative,
               facts_of=None, unrecorded=None, check_stop=lambda: None,
               workspace_repairs=None):
    """Parse a unit; in model mode, repair it while that pays.

    The model mode (a repair header among the unit's `-include`s) parses
    the unit, and, while its own code still has errors and the source text
    shows endpoint calls that have no fact (`unrecorded`), declares or
    edits what clang's errors show missing (:mod:`.rules`, :mod:`.edits`)
    and parses it again, at most :data:`MAX_REPAIR_ROUNDS` times. The
    round with the fewest calls without a fact, then the fewest errors,
    is kept (a repair can make things worse).

    :param parse: ``parse(arguments, unsaved_files)`` -> a translation unit
    :param facts_of: the walk of a parsed unit -> its facts
    :param unrecorded: ``unrecorded(tu, facts)``: how many endpoint calls
      the unit's own files show without a fact; None: repair while there
      are errors
    :param check_stop: raises when the analysis should end (a round is one
      more parse)
    :param workspace_repairs: a store.WorkspaceRepairs: the unit starts
      with what the workspace's other units needed, and offers its own
    :rtype: ParsedUnit
    """
    header = repair_header_of(entry.arguments)
    if header is None:
        tu = parse(entry.arguments, [])
        return ParsedUnit(tu, facts_of(tu) if facts_of else None)
    return _Repairing(
        index, entry, parse=parse, header=header, package_path=package_path,
        relative=relative, facts_of=facts_of, unrecorded=unrecorded,
        check_stop=check_stop, workspace=workspace_repairs).run()


def repair_header_of(arguments):
    """The repair header a unit's arguments force-include, or None."""
    for option, value in zip(arguments, arguments[1:]):
        if option == '-include' and \
                f'/{store.REPAIR_DIR}/' in value.replace(os.sep, '/'):
            return value
    return None


def _inside(file, directory):
    return os.path.abspath(file).startswith(directory.rstrip('/') + '/')


class _Repairing:
    """The rounds of one unit's repairs."""

    def __init__(self, index, entry, *, parse, header, package_path,  # noqa: D107
                 relative, facts_of, unrecorded, check_stop, workspace):
        self.entry = entry
        self.workspace = workspace
        self.parse_with = parse
        self.header = header
        self.package_path = package_path
        self.relative = relative
        self.facts_of = facts_of
        self.unrecorded = unrecorded
        self.check_stop = check_stop
        self.stub_dir = os.path.dirname(os.path.dirname(os.path.dirname(
            header)))
        self.codes = {}
        self.texts = {}
        self.lines = {}
        # {file: (its text with the unit's edits, where they inserted)}
        self.edited = {}

    # --- reading the code ------------------------------------------------

    def read_code(self, file):
        """A file's text as latin-1: a character a byte, as clang counts."""
        if file not in self.codes:
            try:
                self.codes[file] = safe_files.read_bytes(file).decode(
                    'latin-1')
            except OSError:
                self.codes[file] = None
        return self.codes[file]

    def text_of(self, file):
        if file not in self.texts:
            try:
                self.texts[file] = safe_files.read_text(
                    file, errors='replace')
            except OSError:
                self.texts[file] = ''
        return self.texts[file]

    def read_line(self, file, line):
        if file not in self.lines:
            self.lines[file] = self.text_of(file).split('\n')
        lines = self.lines[file]
        return lines[line - 1] if 0 < line <= len(lines) else ''

    def user_file(self, file):
        """The workspace's code: not stand-ins, model or system headers."""
        return not _inside(file, self.stub_dir) and \
            not _inside(file, MODEL_HEADERS_DIR) and \
            not file.startswith(('/usr/', '/opt/'))

    def disk_column(self, file, line, column):
        return applied.disk_column(
            self.edited.get(file, (None, {}))[1], line, column)

    def in_parse(self, file, line, column):
        """A place on disk, as the parse with the edits in memory has it."""
        return file, line, applied.edited_column(
            self.edited.get(file, (None, {}))[1], line, column)

    # --- the rounds --------------------------------------------------------

    def parse(self):
        repairs = store.read_repairs(self.header)
        self.edited = applied.edited_files(repairs, self.read_code)
        tu = self.parse_with(self.entry.arguments, [
            (file, text) for file, (text, _) in self.edited.items()] +
            sorted(overlay.overlays(repairs).items()))
        facts = self.facts_of(tu) if self.facts_of else None
        missing = self.unrecorded(tu, facts) if self.unrecorded else None
        return tu, facts, missing

    def own_errors(self, tu):
        """Errors in the workspace's code, their columns as on disk."""
        return [(message, file, line, self.disk_column(file, line, column))
                for message, file, line, column in error_diagnostics(tu)
                if file and self.user_file(file)]

    def run(self):
        if not store.read_repairs(self.header):
            # a unit never repaired starts with what its package's other
            # units needed (their names, unless this package declares them)
            # and the workspace's (names the workspace declares nowhere)
            store.seed_repairs(self.header, self.relative,
                               package_declarations(self.package_path),
                               self.workspace)
        tu, facts, missing = self.parse()
        errors = self.own_errors(tu)
        header_lines = self.header_error_lines(tu)
        records = store.read_records(self.header)
        best = (self.score(missing, errors, header_lines), 0, tu, facts,
                records)
        rounds = 0
        withdrawn = set()
        while rounds < MAX_REPAIR_ROUNDS:
            conflicting = self.conflicting(header_lines)
            if conflicting:
                # a repair clang rejected (a type a header included later
                # declares as a typedef, a package's other unit's name)
                # breaks the unit's own code: withdrawn, whatever it costs
                withdrawn |= conflicting
                store.withdraw_shared(self.header, conflicting, self.workspace)
                records = store.read_records(self.header)
                store.write_records(self.header, self.relative, {
                    r: rule for r, rule in records.items()
                    if r not in conflicting})
            elif errors and missing != 0:
                # repairing pays only where a call the text shows has no
                # fact
                found = {r: rule for r, rule in self.repairs(
                    tu, errors).items() if r not in withdrawn}
                if not store.add_repairs(self.header, self.relative, found):
                    break
                if any(kind == HEADER for kind, _ in found):
                    self.write_stand_ins_of_repair()
            else:
                if errors and not rounds:
                    self.offer_unpaid(tu, errors)
                break
            self.check_stop()  # each round is one more parse
            rounds += 1
            tu, facts, missing = self.parse()
            errors = self.own_errors(tu)
            header_lines = self.header_error_lines(tu)
            score = self.score(missing, errors, header_lines)
            if score < best[0]:
                best = (score, rounds, tu, facts,
                        store.read_records(self.header))
        (lost_calls, _), best_round, tu, facts, records = best
        if best_round != rounds:
            # a later round made things worse: keep the best, so that later
            # parses of the unit do not pay for it
            store.write_records(self.header, self.relative, records)
        if best_round:
            store.share_repairs(self.header, set(records), self.workspace)
        return ParsedUnit(tu, facts, rounds, records,
                          lost_calls if self.unrecorded else None)

    def offer_unpaid(self, tu, errors):
        """Offer what a unit's errors show missing, without parsing it again.

        Every call of the unit has its fact, so repairing it would not pay.
        But the names its errors show missing (a library's function used
        qualified, a macro) are missing in the package's and the workspace's
        other units too: those parsed later start with them, at no parse of
        their own. Clang has not seen these repairs: one that a later unit
        rejects is withdrawn there, as any shared repair. A header repair is
        not offered: its stand-ins were never written.
        """
        found = self.repairs(tu, errors)
        store.share_repairs(self.header, {
            repair for repair in found if repair[0] != HEADER},
            self.workspace)

    @staticmethod
    def score(missing, errors, header_lines):
        """Which parse is kept: the lowest score wins.

        The fewest calls without a fact, then the fewest errors in the
        workspace's code and in the repair header.
        """
        return missing or 0, len(errors) + len(header_lines)

    def header_error_lines(self, tu):
        """The repair header's lines an error is on, or its note points at.

        A repair can conflict with a declaration clang reads before it (the
        error is in the header) or after it (the error is at the other
        declaration, and its note at the repair's).
        """
        header = os.path.abspath(self.header)
        return {line for _, file, line, _, notes
                in errors_with_notes(tu, messages.REDECLARED.search)
                for file, line in [(file, line)] + [
                    (at, number) for _, at, number, _ in notes]
                if file and os.path.abspath(file) == header} | {
            line for _, file, line, _ in error_diagnostics(tu)
            if file and os.path.abspath(file) == header}

    def conflicting(self, header_lines):
        """The unit's repairs whose declarations clang reports errors in.

        :param header_lines: the repair header's lines of the parse's
          errors (:meth:`header_error_lines`)
        """
        if not header_lines:
            return set()
        return render.repairs_at(store.read_repairs(self.header),
                                 self.relative, header_lines)

    def repairs(self, tu, errors):
        """{(kind, name): rule id} of the declarations and edits to add."""
        own_files = {self.entry.file} | {
            i.include.name for i in tu.get_includes()
            if i.include is not None and self.user_file(i.include.name)}
        # the notes of the errors whose rules read them (the candidates of
        # a call no overload matches: the class they are members of)
        notes = {(message, file, line, self.disk_column(file, line, column)):
                 found for message, file, line, column, found
                 in errors_with_notes(tu, needs_notes)}
        found = found_repairs(
            [error + ((notes[error],) if error in notes else ())
             for error in errors], self.read_line,
            texts=[self.text_of(f) for f in sorted({e[1] for e in errors})],
            declared=set().union(*(
                file_declarations(f, self.text_of(f))
                for f in sorted(own_files))),
            stand_in=lambda relative: os.path.isfile(
                os.path.join(self.stub_dir, relative)))

        def on_disk(file, arguments):
            return None if arguments is None else [
                (line, self.disk_column(file, line, column), argument_type)
                for line, column, argument_type in arguments]
        made = edits.edits_from_diagnostics(errors, self.read_code)
        # (edits that need the parse's declarations: the parameters a call
        # passes its arguments to)
        made |= edits.edits_from_notes(
            [(message, file, line, self.disk_column(file, line, column),
              notes)
             for message, file, line, column, notes
             in errors_with_notes(tu, edits.needs_notes)
             if file and self.user_file(file)],
            self.read_code,
            parameter_types=lambda *at, callee=None: parameter_types(
                tu, *at, object_at=callee and self.in_parse(*callee)),
            parameter_type=lambda *at: parameter_type(tu, *at),
            call_arguments=lambda file, line, column: on_disk(
                file, call_arguments(tu, *self.in_parse(file, line, column))))
        # one edit a place: one made in an earlier round stays (a second
        # would wrap the first)
        edited_places = {name for kind, name in store.read_repairs(
            self.header) if is_edit(kind)}
        for kind, place in made:
            if place not in edited_places:
                found.setdefault((kind, place), kind.partition(':')[0])
        return found

    def write_stand_ins_of_repair(self):
        """Write the stand-ins the headers a repair header includes need.

        A model header included by a repair (``rclcpp/rclcpp.hpp``, for an
        ``rclcpp::`` name used before any include brought it in) includes
        generated ones in turn, which the unit's own scan never met.
        """
        from colcon_rsia.frontend.cpp.model_mode import \
            prepare_model_arguments
        try:
            prepare_model_arguments(
                source=self.header, arguments=self.entry.arguments,
                package_path=self.package_path, workspace_package_dirs=[],
                stub_dir=self.stub_dir, directory=self.entry.directory)
        except (OSError, ValueError):
            pass  # the parse then reports the missing header, as before


_declarations = {}
_declarations_lock = threading.Lock()


def package_declarations(package_path):
    """The names a package's own C++ files declare (read once)."""
    with _declarations_lock:
        if package_path not in _declarations:
            texts = []
            for root, dirs, files in os.walk(package_path):
                dirs[:] = [d for d in dirs if d not in SKIPPED_DIRECTORIES
                           and not d.startswith('.')]
                for name in files:
                    if name.endswith(CXX_FILES):
                        try:
                            texts.append(safe_files.read_text(
                                os.path.join(root, name), errors='replace'))
                        except OSError:
                            pass  # named by the checks before the parse
            _declarations[package_path] = declared_names(texts)
        return _declarations[package_path]


def workspace_repairs(path, package_dirs):
    """The store.WorkspaceRepairs of a workspace, kept in `path`."""
    declared = set()
    for directory in package_dirs:
        declared |= package_declarations(os.path.abspath(directory))
    return store.WorkspaceRepairs(path, declared)
