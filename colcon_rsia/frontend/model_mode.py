# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The *model* header mode: parse a package without the real ROS headers.

A translation unit is parsed with the tool's own small declarations of the
ROS API (``model_headers/``) in place of the real headers, and every include
that neither those nor the package's own source tree provide gets a
generated stand-in in a stub directory:

- ``pkg/Name.h`` (a message) becomes ``pkg::Name_<ContainerAllocator>`` with
  ``Name``, ``NamePtr``, ``NameConstPtr``, ``Name::Ptr`` and
  ``Name::ConstPtr``, exactly the names and template shape generated message
  headers have (user callbacks' USRs embed them);
- a service ``pkg/Name.h`` becomes the service struct with ``Request`` and
  ``Response``; an action ``pkg/NameAction.h`` the action with its goal,
  result and feedback; ``pkg/NameConfig.h`` a dynamic_reconfigure config;
- anything else (third-party and ROS headers the model lacks) is empty.

Fields cannot be guessed, so every stand-in derives from
``rsia_model::Fields``: one catch-all member for each name the sources use
after ``.`` or ``->`` (written to the generated ``rsia_model/fields.h``),
which keeps expressions on message fields -- and the calls around them --
well-formed. The result is the same facts as with the real headers, parsed
several times faster, and on a machine without ROS.

The generated files only ever grow (a stub directory may be shared by the
translation units of a package, parsed in parallel): writes are atomic and
serialised by a lock.
"""

import glob
import os
import re
import threading

from colcon_rsia import safe_files

MODEL_HEADERS_DIR = os.path.join(
    os.path.dirname(os.path.abspath(__file__)), 'model_headers')

# the version of the stand-ins' content: a stand-in of another version is
# written again
STUB_VERSION = 1
_STUB_MARKER = f'// colcon-rsia stand-in v{STUB_VERSION}'

FIELDS_HEADER = os.path.join('rsia_model', 'fields.h')
IMPLICIT_MESSAGES_HEADER = os.path.join('rsia_model', 'implicit_messages.h')

# include prefixes of C/POSIX/Linux system headers: left to the compiler
SYSTEM_PREFIXES = (
    'sys/', 'bits/', 'linux/', 'arpa/', 'netinet/', 'asm/', 'asm-generic/',
    'net/', 'netpacket/', 'scsi/', 'rpc/', 'ext/', 'tr1/', 'experimental/',
    'gnu/', 'c++/',
)

# directory names that never hold sources: their headers are generated
# (message headers of devel/ or build/ pull in real ROS headers)
BUILD_DIR_NAMES = frozenset({
    'build', 'devel', 'install', 'log', 'build_isolated', 'devel_isolated',
    'install_isolated'})
# a directory holding one of these is no source tree
BUILD_MARKERS = ('COLCON_IGNORE', 'CATKIN_IGNORE', 'AMENT_IGNORE',
                 'CMakeCache.txt')

# how many `..` an unresolved quote include may climb (one stand-in
# directory level each)
MAX_UP_LEVELS = 8

_INCLUDE = re.compile(
    r'^[ \t]*#[ \t]*(?:include|include_next|import)[ \t]*([<"])([^>"\n]+)[>"]',
    re.MULTILINE)
COMMENT_OR_STRING = re.compile(
    r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'',
    re.DOTALL)
_MEMBER = re.compile(r'(?:\.|->)\s*(?:template\s+)?([A-Za-z_]\w*)')
# `.as<T>()`, `->template get<T>(key)`: a member called with template
# arguments (one level of nesting); `.data` alone: a member used as a value
_TEMPLATE_MEMBER = re.compile(
    r'(?:\.|->)\s*(?:template\s+)?([A-Za-z_]\w*)\s*'
    r'<[^;(){}<>]*(?:<[^;(){}<>]*>[^;(){}<>]*)*>\s*\(')
_VALUE_MEMBER = re.compile(r'(?:\.|->)\s*([A-Za-z_]\w*)\b(?!\s*[(<])')
_CONSTANT = re.compile(r'\b[A-Z]\w*\s*::\s*([A-Z][A-Z0-9_]*)\b')
# the type of a ROS 2 message field: DiagnosticStatus::_level_type
_FIELD_TYPE = re.compile(r'::\s*(_[a-z][a-z0-9_]*_type)\b')
_MSGS_TYPE = re.compile(r'\b([a-z][a-z0-9_]*_msgs)\s*::\s*([A-Z][A-Za-z0-9]*)\b')
_ROS2_MSGS_TYPE = re.compile(
    r'\b([a-z][a-z0-9_]*_msgs)\s*::\s*msg\s*::\s*([A-Z][A-Za-z0-9]*)\b')
_IDENTIFIER = re.compile(r'^[A-Za-z_]\w*$')
_CAMEL = re.compile(r'^[A-Z][A-Za-z0-9]*$')
_PACKAGE = re.compile(r'^[a-z][a-z0-9_]*$')

# names that can never be members: C++ keywords and alternative tokens,
# macros every translation unit has, the members of rsia_model::Any itself
_NOT_MEMBERS = frozenset("""
    alignas alignof and and_eq asm auto bitand bitor bool break case catch
    char char8_t char16_t char32_t class compl concept const consteval
    constexpr constinit const_cast continue co_await co_return co_yield
    decltype default delete do double dynamic_cast else enum explicit export
    extern false float for friend goto if inline int long mutable namespace
    new noexcept not not_eq nullptr operator or or_eq private protected public
    register reinterpret_cast requires return short signed sizeof static
    static_assert static_cast struct switch template this thread_local throw
    true try typedef typeid typename union unsigned using virtual void
    volatile wchar_t while xor xor_eq
    linux unix i386 errno stdin stdout stderr NULL EOF assert offsetof
    major minor makedev setjmp va_arg va_start va_end va_copy
    Any AnyElement Fields begin end ContainerAllocator boost std ros
""".split())

# the costly standard headers of rsia_model/std.h (what the real ROS headers
# include), each with the names that need it: the model includes one only
# when the sources use such a name, which halves the parse time of most TUs
# (a header with `using namespace std` gets them all)
_STD_HEADERS = {
    'ALGORITHM': ('sort stable_sort partial_sort nth_element find find_if find_if_not '
                  'find_end find_first_of adjacent_find count count_if mismatch equal '
                  'search search_n copy copy_if copy_n copy_backward move_backward fill '
                  'fill_n transform generate generate_n remove remove_if remove_copy '
                  'replace replace_if replace_copy reverse reverse_copy rotate shuffle '
                  'random_shuffle unique unique_copy partition stable_partition '
                  'lower_bound upper_bound binary_search equal_range merge inplace_merge '
                  'includes set_union set_intersection set_difference min max minmax '
                  'min_element max_element minmax_element clamp lexicographical_compare '
                  'next_permutation prev_permutation all_of any_of none_of for_each '
                  'swap_ranges iter_swap is_sorted is_permutation make_heap push_heap '
                  'pop_heap sort_heap'),
    'CMATH': ('sqrt cbrt hypot pow exp exp2 expm1 log log10 log2 log1p sin cos tan asin '
              'acos atan atan2 sinh cosh tanh fabs abs floor ceil round lround llround '
              'trunc fmod remainder copysign isnan isinf isfinite fmin fmax nan signbit '
              'modf frexp ldexp'),
    'COMPLEX': 'complex',
    'FUNCTIONAL': ('function bind placeholders ref cref mem_fn reference_wrapper hash plus '
                   'minus multiplies divides negate equal_to not_equal_to greater less '
                   'greater_equal less_equal logical_and logical_or logical_not invoke '
                   'not_fn'),
    'IOMANIP': 'setprecision setw setfill setbase put_time get_time quoted',
    'IOSTREAM': 'cout cerr clog cin wcout wcerr wclog wcin',
    'LIST': 'list',
    'MEMORY': ('shared_ptr unique_ptr weak_ptr make_shared make_unique allocate_shared '
               'enable_shared_from_this static_pointer_cast dynamic_pointer_cast '
               'const_pointer_cast reinterpret_pointer_cast addressof allocator_traits '
               'auto_ptr default_delete'),
    'MUTEX': ('mutex recursive_mutex timed_mutex recursive_timed_mutex lock_guard '
              'unique_lock scoped_lock call_once once_flag try_lock defer_lock adopt_lock '
              'try_to_lock'),
    'SET': 'set multiset',
    'SSTREAM': ('stringstream ostringstream istringstream stringbuf basic_stringstream '
                'basic_ostringstream basic_istringstream endl flush ends ws'),
    'UNORDERED_MAP': 'unordered_map unordered_multimap',
}
_STD_QUALIFIED = {
    name: re.compile(r'\bstd\s*::\s*(?:' + '|'.join(words.split()) + r')\b')
    for name, words in _STD_HEADERS.items()}
# C math is also called unqualified, and its macros are used bare
_C_MATH = re.compile(
    r'\b(?:' + '|'.join(_STD_HEADERS['CMATH'].split()) + r')\s*\(|'
    r'\bM_[A-Z0-9_]+\b|\b(?:HUGE_VAL|INFINITY|NAN)\b')
_USING_STD = re.compile(r'\busing\s+namespace\s+std\s*;')

# namespaces never guessed from an unknown include directory: the model's own
# and those of messages
_MODEL_NAMESPACES = frozenset(
    name for name in os.listdir(MODEL_HEADERS_DIR)
    if os.path.isdir(os.path.join(MODEL_HEADERS_DIR, name))) | {'std'}
# the libraries the model headers stand for (their include directories)
_MODEL_LIBRARIES = sorted(_MODEL_NAMESPACES - {'std', 'rsia_model'})
UNKNOWN_DIR = os.path.join('rsia_model', 'unknown')

_lock = threading.Lock()
_model_includes_cache = {}
_system_dirs_cache = []


def prepare_model_arguments(*, source, arguments, package_path,
                            workspace_package_dirs, stub_dir, directory=None):
    """Return the libclang arguments of the model mode for one TU.

    Keeps ``-D``, ``-U``, ``-std`` and the include directories inside the
    package or a workspace source directory, puts the model headers first
    and the stub directory after the kept directories, and writes a stand-in
    into `stub_dir` for every include of the source (and, recursively, of
    the package's headers and the model headers it includes) that nothing
    there provides.

    :param str source: the TU's main file
    :param list arguments: the TU's libclang arguments from the compile
      database (see :func:`colcon_rsia.frontend.compile_db.clang_arguments`)
    :param str package_path: the package's source directory
    :param workspace_package_dirs: the source directories of the
      workspace's packages (their headers are the workspace's own)
    :param str stub_dir: where stand-ins are written (created if missing;
      never inside a package's source directory)
    :param str directory: the compile command's directory, for relative
      include directories (default: the current directory)
    :rtype: list
    """
    roots = [_real(package_path)] + [_real(d) for d in workspace_package_dirs]
    stub_dir = os.path.abspath(stub_dir)
    if any(_inside(_real(stub_dir), root) for root in roots):
        raise ValueError(
            f"the stub directory '{stub_dir}' lies in a package's source "
            'directory; stand-ins are never written among the sources')
    kept, search = _filter_arguments(arguments, roots, directory)
    # a built workspace's database names the other packages' installed
    # headers, outside the sources: their sources' include/ stand for them
    # (a wrapper's body is read there)
    for package_dir in workspace_package_dirs:
        include = os.path.join(_real(package_dir), 'include')
        if os.path.isdir(include) and ('-I', include) not in search:
            kept += ['-I', include]
            search.append(('-I', include))
    # the workspace's own copy of a library the model stands for (a
    # ros2_control checkout has the real controller_interface/): the real
    # headers win there, the model everywhere else
    own_first = [(option, directory) for option, directory in search
                 if option != '-iquote' and any(
                     os.path.isdir(os.path.join(directory, top))
                     for top in _MODEL_LIBRARIES)]
    scanner = _Scanner(roots=roots, search=search, stub_dir=stub_dir,
                       before_model=[d for _, d in own_first])
    scanner.scan(os.path.abspath(source))
    # the sources as code: no comments, literals or include lines
    codes = [_code_only(text) for text in scanner.user_texts]
    up_dirs, own = _write_stand_ins(scanner, codes, stub_dir)
    result = [word for pair in own_first for word in pair] + \
        ['-I', MODEL_HEADERS_DIR] + kept + ['-I', stub_dir]
    result += _std_defines(codes)
    result += _export_macro_defines(codes)
    result += [f'-DRSIA_MODEL_OWN_{namespace}' for namespace in own]
    if scanner.ros2:
        # the headers ROS 1 and ROS 2 share by name (tf2_ros/*.h,
        # message_filters/*.h, ...) take their ROS 2 shape, whatever the
        # order of the unit's includes
        result.append('-DRSIA_MODEL_RCLCPP=1')
    for up_dir in up_dirs:
        result += ['-I', up_dir]
    return result


# --- arguments ---------------------------------------------------------------


_INCLUDE_OPTIONS = ('-I', '-isystem', '-iquote', '-idirafter')


# the model headers this module writes into the stub directory
GENERATED_PREFIX = 'rsia_model/'
# includes only ROS 2 code has: rclcpp, generated ROS 2 interfaces, and
# the `.hpp` headers of libraries whose ROS 1 versions have `.h` ones
_ROS2_INCLUDE = re.compile(
    r'^(?:rclcpp(?:_\w+)?/'
    r'|\w+/(?:msg|srv|action)/\w+\.hpp$'
    r'|(?:image_transport|message_filters|realtime_tools|diagnostic_updater'
    r'|tf2_ros)/.*\.hpp$)')


def _filter_arguments(arguments, roots, directory):
    """Return (kept arguments, [(kind, dir)] of the kept include dirs)."""
    kept = []
    search = []
    base = directory or os.getcwd()
    i = 0
    while i < len(arguments):
        arg = arguments[i]
        option, value, used = _split_option(arguments, i)
        i += used
        if option in ('-D', '-U'):
            kept += [option + value] if value else []
        elif option == '-std':
            kept.append(arg)
        elif option in _INCLUDE_OPTIONS and value:
            path = os.path.normpath(os.path.join(base, value))
            if _in_source_tree(path, roots):
                kept += [option, path]
                search.append((option, path))
    return kept, search


def _split_option(arguments, i):
    """Return (option, value, number of arguments used) at position i."""
    arg = arguments[i]
    if arg.startswith('-std='):
        return '-std', arg[5:], 1
    for option in ('-isystem', '-iquote', '-idirafter', '-I', '-D', '-U'):
        if arg == option:
            value = arguments[i + 1] if i + 1 < len(arguments) else ''
            return option, value, 2
        if arg.startswith(option):
            return option, arg[len(option):], 1
    return None, None, 1


def _real(path):
    return os.path.realpath(os.path.abspath(path))


def _inside(path, root):
    return path == root or path.startswith(root.rstrip('/') + '/')


def _in_source_tree(path, roots):
    """Whether a directory lies in a source tree (never a build tree)."""
    real = _real(path)
    for root in roots:
        if not _inside(real, root):
            continue
        relative = os.path.relpath(real, root)
        parts = [] if relative == '.' else relative.split(os.sep)
        current = root
        for part in parts:
            if part in BUILD_DIR_NAMES:
                return False
            current = os.path.join(current, part)
            if any(os.path.exists(os.path.join(current, marker))
                   for marker in BUILD_MARKERS):
                return False
        return True
    return False


# --- include scan ------------------------------------------------------------

class _Scanner:
    """Follows the includes of a source through the files we can read."""

    def __init__(self, *, roots, search, stub_dir, before_model=()):
        self.roots = roots
        self.search = search
        self.stub_dir = stub_dir
        self.quote_dirs = [d for kind, d in search if kind == '-iquote']
        # in the order the parse searches them (see prepare_model_arguments)
        self.angle_dirs = list(before_model) + [MODEL_HEADERS_DIR] + [
            d for kind, d in search
            if kind != '-iquote' and d not in before_model]
        self.visited = set()
        # include name -> 'stub' (a stand-in by its name) | 'empty' (a
        # system header this machine lacks)
        self.missing = {}
        self.user_texts = []
        self._isfile = {}
        # whether the package's own code includes a ROS 2 header (the dual
        # model headers include ROS 2 ones behind #ifdef: theirs never count)
        self.ros2 = False

    def scan(self, source):
        todo = [source]
        while todo:
            path = todo.pop()
            if path in self.visited:
                continue
            self.visited.add(path)
            user_file = not path.startswith(MODEL_HEADERS_DIR + os.sep)
            for quoted, name in self._includes(path):
                found = self.resolve(name, quoted, os.path.dirname(path))
                if user_file and _ROS2_INCLUDE.match(name):
                    self.ros2 = True
                if found is not None:
                    if found not in self.visited and self._scannable(found):
                        todo.append(found)
                    continue
                if self._is_system(name):
                    if not self._in_system_dirs(name):
                        self.missing[name] = 'empty'
                    continue
                if name.startswith(GENERATED_PREFIX):
                    continue  # merged into the stub directory, never stood in
                self.missing.setdefault(name, 'stub')

    def _includes(self, path):
        if path.startswith(MODEL_HEADERS_DIR + os.sep):
            cached = _model_includes_cache.get(path)
            if cached is None:
                cached = _read_includes(_read_text(path) or '')
                _model_includes_cache[path] = cached
            return cached
        text = _read_text(path)
        if text is None:
            return []
        self.user_texts.append(text)
        return _read_includes(text)

    def _scannable(self, path):
        if path.startswith(MODEL_HEADERS_DIR + os.sep):
            return True
        real = _real(path)
        return any(_inside(real, root) for root in self.roots)

    def resolve(self, name, quoted, including_dir):
        """The file an include finds in the model or source directories."""
        if os.path.isabs(name):
            return name if self._exists(name) else None
        dirs = []
        if quoted:
            dirs = [including_dir] + self.quote_dirs
        dirs += self.angle_dirs
        for directory in dirs:
            candidate = os.path.normpath(os.path.join(directory, name))
            if self._exists(candidate):
                return candidate
        return None

    def _exists(self, path):
        found = self._isfile.get(path)
        if found is None:
            found = os.path.isfile(path)
            self._isfile[path] = found
        return found

    @staticmethod
    def _is_system(name):
        return '/' not in name or name.startswith(SYSTEM_PREFIXES)

    def _in_system_dirs(self, name):
        return any(self._exists(os.path.join(d, name))
                   for d in _system_include_dirs())


def _read_text(path):
    try:
        # checked: a header may be a link to /dev/zero, or a FIFO
        data = safe_files.read_bytes(path)
    except OSError:
        return None
    return data.decode('utf-8', errors='surrogateescape')


def _read_includes(text):
    return [(m.group(1) == '"', m.group(2).strip())
            for m in _INCLUDE.finditer(text)]


def _system_include_dirs():
    """The compiler's own include directories (standard, POSIX, Linux)."""
    if not _system_dirs_cache:
        from colcon_rsia.frontend.compile_db import find_resource_dir
        dirs = []
        resource_dir = find_resource_dir()
        if resource_dir:
            dirs.append(os.path.join(resource_dir, 'include'))
        for pattern in ('/usr/include/c++/*', '/usr/include/*/c++/*',
                        '/usr/include/c++/*/backward'):
            dirs += sorted(glob.glob(pattern), reverse=True)
        dirs += ['/usr/local/include']
        dirs += sorted(glob.glob('/usr/include/*-linux-gnu*'))
        dirs += ['/usr/include']
        _system_dirs_cache.append([d for d in dirs if os.path.isdir(d)])
    return _system_dirs_cache[0]


# --- what the sources use ----------------------------------------------------

# visibility and export macros, defined by headers CMake generates into the
# build tree (or by ones the model lacks): FOO_PUBLIC class Bar
# at declaration level, before a name (`class FOO_PUBLIC Node`,
# `FOO_LOCAL void f();`): a value such as RMW_QOS_POLICY_DURABILITY_
# TRANSIENT_LOCAL (followed by `;`, `,` or `)`) is no export macro
_EXPORT_MACRO = re.compile(
    r'\b([A-Z][A-Z0-9_]*_(?:EXPORT|PUBLIC|LOCAL|IMPORT|API|PUBLIC_TYPE'
    r'|DECLSPEC|VISIBILITY))\b(?=\s+[A-Za-z_~])')


def _export_macro_defines(codes):
    """``-DFOO_PUBLIC=`` for each export macro no scanned file defines."""
    used = set()
    defined = set()
    for code in codes:
        used.update(_EXPORT_MACRO.findall(code))
        defined.update(re.findall(r'^\s*#\s*define\s+(\w+)', code, re.M))
    return [f'-D{name}=' for name in sorted(used - defined)]


def _code_only(text):
    """The text without comments, literals and include lines."""
    return _INCLUDE.sub(' ', COMMENT_OR_STRING.sub(' ', text))


def _used_names(codes):
    """(members, constants, field types, {pkg: {include}} of *_msgs types).

    The include is the message's header: ``std_msgs/Header.h`` (ROS 1) or
    ``std_msgs/msg/header.hpp`` (ROS 2).
    """
    members = set()
    constants = set()
    field_types = set()
    msgs_types = {}
    templates = set()
    values = set()
    for code in codes:
        members.update(m.group(1) for m in _MEMBER.finditer(code))
        templates.update(m.group(1) for m in _TEMPLATE_MEMBER.finditer(code))
        values.update(m.group(1) for m in _VALUE_MEMBER.finditer(code))
        constants.update(m.group(1) for m in _CONSTANT.finditer(code))
        field_types.update(m.group(1) for m in _FIELD_TYPE.finditer(code))
        for m in _MSGS_TYPE.finditer(code):
            name = re.sub(r'(?:ConstPtr|Ptr)$', '', m.group(2))
            if name:
                msgs_types.setdefault(m.group(1), set()).add(
                    f'{m.group(1)}/{name}.h')
        for m in _ROS2_MSGS_TYPE.finditer(code):
            msgs_types.setdefault(m.group(1), set()).add(
                f'{m.group(1)}/msg/{_snake_case(m.group(2))}.hpp')
    members = {n for n in members if _member_ok(n)}
    constants = {n for n in constants if _member_ok(n)} - members
    # a member function template, unless some use takes it for a value
    templates = {n for n in templates - values if n in members}
    return members - templates, constants, field_types - members, \
        msgs_types, templates


def _std_defines(codes):
    """-D options naming the costly standard headers the sources need."""
    if any(_USING_STD.search(code) for code in codes):
        return []  # unqualified names from anywhere: everything
    needed = set()
    for code in codes:
        for name, pattern in _STD_QUALIFIED.items():
            if name not in needed and pattern.search(code):
                needed.add(name)
        if 'CMATH' not in needed and _C_MATH.search(code):
            needed.add('CMATH')
    return ['-DRSIA_MODEL_LEAN_STD'] + [
        f'-DRSIA_MODEL_STD_{name}' for name in sorted(needed)]


def _member_ok(name):
    # names beginning with `__` or `_X` are reserved to the implementation
    return bool(_IDENTIFIER.match(name)) and name not in _NOT_MEMBERS and \
        not name.lower().startswith('rsia') and \
        not re.match(r'_[_A-Z]', name)


def _service_evidence(name, codes):
    """Whether the sources use `name` as a service (Request/Response)."""
    pattern = re.compile(
        r'\b' + re.escape(name) +
        r'(?:\s*::\s*(?:Request|Response)(?:Type)?\b|(?:Request|Response)\b)')
    return any(pattern.search(code) for code in codes)


def _message_evidence(name, codes):
    """Whether the sources use `name` as a message (pointers to it)."""
    pattern = re.compile(
        r'\b' + re.escape(name) + r'(?:\s*::\s*(?:Const)?Ptr\b|(?:Const)?Ptr\b)')
    return any(pattern.search(code) for code in codes)


# --- stand-ins ---------------------------------------------------------------

def _write_stand_ins(scanner, codes, stub_dir):
    """Write the stand-ins one TU needs.

    :returns: (the extra include dirs, the namespaces of unknown includes
      that the TU declares itself)
    """
    members, constants, field_types, msgs_types, templates = \
        _used_names(codes)
    stubs = {}   # include name -> content
    for name, kind in sorted(scanner.missing.items()):
        if kind == 'empty':
            stubs[name] = _empty_stub(name)
        else:
            stubs.update(_stand_ins_for(name, codes))
    unknown, own = _unknown_namespaces(stubs, codes)
    implicit = []
    for package, includes in sorted(msgs_types.items()):
        for include in sorted(includes):
            if include in stubs or scanner.resolve(
                    include, False, stub_dir) is not None:
                continue
            for stub_name, content in _stand_ins_for(include, codes).items():
                stubs.setdefault(stub_name, content)
            implicit.append(include)
    up_dirs = set()
    with _lock:
        os.makedirs(stub_dir, exist_ok=True)
        # stand-ins before the headers that include them: another TU of the
        # package may be parsing already
        for name, content in stubs.items():
            try:
                target, up = _stub_path(stub_dir, name)
                if target is None:
                    continue
                _write_stub(target, content)
            except OSError:
                continue  # e.g. a name that is also a directory: the
                # include stays unresolved, as with no stand-in at all
            if up:
                up_dirs.add(up)
        for namespace, names in unknown.items():
            _merge_unknown(stub_dir, namespace, names)
        _merge_implicit(stub_dir, implicit)
        _merge_fields(stub_dir, members, constants, field_types, templates)
    return sorted(up_dirs), own


def _stub_path(stub_dir, name):
    """Where the stand-in of an include goes: (path, extra include dir)."""
    if os.path.isabs(name):
        return None, None  # never written outside the stub directory
    normalized = os.path.normpath(name)
    parts = normalized.split(os.sep)
    up = 0
    while parts and parts[0] == '..':
        parts.pop(0)
        up += 1
    if not parts or up > MAX_UP_LEVELS or '..' in parts:
        return None, None
    if not up:
        return os.path.join(stub_dir, *parts), None
    # `#include "../x.h"` from an include dir `_up/a` finds `_up/x.h`
    base = os.path.join(stub_dir, '_up')
    up_dir = os.path.join(base, *(['a'] * up))
    os.makedirs(up_dir, exist_ok=True)
    return os.path.join(base, *parts), up_dir


def _write_stub(target, content):
    existing = _read_text(target)
    if existing == content:
        return
    if existing is not None and existing.startswith(_STUB_MARKER):
        kinds = {_stub_kind(existing), _stub_kind(content)}
        if kinds <= {'message', 'service', 'service_message'} and \
                len(kinds) > 1:
            # one TU uses the name as a message, another as a service: the
            # combined form serves both (it only ever grows)
            if _stub_kind(existing) == 'service_message':
                return
            content = _combined_stub_from(content)
    write_atomically(target, content)


def _stub_kind(text):
    match = re.search(r'kind=(\w+)', text.split('\n', 1)[0])
    return match.group(1) if match else None


def write_atomically(path, content):
    """Write a text file whole or not at all (readers never see half).

    Stand-ins keep undecodable names as they were read.
    """
    safe_files.write_text_atomically(path, content, errors='surrogateescape')


def _merge_fields(stub_dir, members, constants, field_types=(),
                  templates=()):
    """Grow rsia_model/fields.h to hold these member, constant, type names.

    :param templates: members called with template arguments only
    """
    path = os.path.join(stub_dir, FIELDS_HEADER)
    old = _read_text(path) or ''
    if not old.startswith(_STUB_MARKER):
        old = ''
    old_members = set(re.findall(r'RSIA_MODEL_FIELD\((\w+)\)', old))
    old_constants = set(re.findall(r'RSIA_MODEL_CONSTANT\((\w+),', old))
    old_types = set(re.findall(r'RSIA_MODEL_FIELD_TYPE\((\w+)\)', old))
    old_templates = set(re.findall(
        r'RSIA_MODEL_FIELD_TEMPLATE\((\w+)\)', old))
    if old and members <= old_members | old_templates and \
            constants <= old_constants | old_members and \
            set(field_types) <= old_types | old_members and \
            set(templates) <= old_templates | old_members:
        return
    # a name keeps the first form it was given (units share the file)
    all_templates = sorted(
        (old_templates | set(templates)) - old_members)
    all_members = sorted((old_members | members) - set(all_templates))
    taken = set(all_members) | set(all_templates)
    all_constants = sorted((old_constants | constants) - taken)
    all_types = sorted((old_types | set(field_types)) - taken)
    lines = [
        f'{_STUB_MARKER} kind=fields',
        '// the member names used after `.` / `->` in the analysed sources,',
        '// the `Type::CONSTANT` names and the `Type::_field_type` names;',
        '// included twice by rsia_model/message.h (no include guard), a name',
        '// that is a macro there is left out']
    for name in all_members:
        lines += [f'#ifndef {name}', f'RSIA_MODEL_FIELD({name})', '#endif']
    for name in all_templates:
        lines += [f'#ifndef {name}', f'RSIA_MODEL_FIELD_TEMPLATE({name})',
                  '#endif']
    for name in all_types:
        lines += [f'#ifndef {name}', f'RSIA_MODEL_FIELD_TYPE({name})',
                  '#endif']
    # distinct values: constants may be `case` labels of one switch
    for i, name in enumerate(all_constants):
        lines += [f'#ifndef {name}', f'RSIA_MODEL_CONSTANT({name}, {i + 1})',
                  '#endif']
    write_atomically(path, '\n'.join(lines) + '\n')


def _merge_implicit(stub_dir, implicit):
    """Grow rsia_model/implicit_messages.h by these includes."""
    path = os.path.join(stub_dir, IMPLICIT_MESSAGES_HEADER)
    old = _read_text(path) or ''
    old_includes = set(re.findall(r'#include <([^>]+)>', old)) \
        if old.startswith(_STUB_MARKER) else set()
    if set(implicit) <= old_includes and old.startswith(_STUB_MARKER):
        return
    lines = [
        f'{_STUB_MARKER} kind=implicit',
        '// messages of *_msgs packages the sources name without including',
        '// them (the real message headers include what their fields use)']
    lines += [f'#include <{n}>' for n in sorted(old_includes | set(implicit))]
    write_atomically(path, '\n'.join(lines) + '\n')


def _empty_stub(name):
    lines = [f'{_STUB_MARKER} kind=empty: <{_printable(name)}>',
             '// an include the model mode does not provide',
             '#pragma once']
    namespace = _guessed_namespace(name)
    if namespace:
        # what the sources use of `namespace::`, if it is declared nowhere
        # else (model_mode.py defines RSIA_MODEL_OWN_<ns> where it is)
        header = f'rsia_model/unknown/{namespace}.h'
        lines += [
            f'#if !defined(RSIA_MODEL_OWN_{namespace}) && '
            f'__has_include(<{header}>)',
            f'#include <{header}>',
            '#endif']
    return '\n'.join(lines) + '\n'


# include directories whose libraries use another namespace name
_NAMESPACE_OF_DIRECTORY = {'opencv2': 'cv', 'opencv': 'cv'}


def _guessed_namespace(include):
    """The namespace an unknown `dir/...` include probably declares."""
    parts = include.split('/')
    if len(parts) < 2 or not _PACKAGE.match(parts[0]):
        return None
    namespace = _NAMESPACE_OF_DIRECTORY.get(parts[0], parts[0])
    if namespace in _MODEL_NAMESPACES or namespace.endswith(
            ('_msgs', '_srvs')) or not _member_ok(namespace):
        return None
    return namespace


def _unknown_namespaces(stubs, codes):
    """Guess what unknown includes declare.

    :returns: ({namespace: (types {name: static members}, objects,
      constants)}, sorted namespaces the TU declares itself)


    For the namespace of each unknown include directory (a package's name is
    its namespace, by ROS convention), the names the sources use after
    `namespace::` are declared: CamelCase names (and names used to declare
    a variable) as catch-all classes, ALL_CAPS names as constants, others as
    catch-all objects (functions, variables). Templates (`ns::Name<`) are
    left undeclared. A namespace the sources open themselves, or one with
    messages of this TU, is left alone (and named in the second result).
    """
    namespaces = {_guessed_namespace(name) for name, content in stubs.items()
                  if 'kind=empty' in content.split('\n', 1)[0]} - {None}
    with_messages = {name.split('/')[0] for name, content in stubs.items()
                     if 'kind=empty' not in content.split('\n', 1)[0]}
    result = {}
    own = []
    for namespace in sorted(namespaces):
        opened = re.compile(r'\bnamespace\s+' + namespace + r'\b')
        if namespace in with_messages or any(
                opened.search(code) for code in codes):
            own.append(namespace)
            continue
        use = re.compile(
            r'(?<![\w:])' + namespace + r'\s*::\s*([A-Za-z_]\w*)'
            r'(\s*<|\s*::\s*([A-Za-z_]\w*)|\s*[&*]*\s*[A-Za-z_]\w*\s*[;=({,)\[])?')
        types, objects, constants, templates = {}, set(), set(), set()
        for code in codes:
            for match in use.finditer(code):
                name, after, member = match.group(1), match.group(2), \
                    match.group(3)
                if not _member_ok(name) or name == namespace:
                    continue
                if after and after.strip() == '<':
                    templates.add(name)
                elif member and re.match(r'^[a-z][a-z0-9_]*$', name) and \
                        _CAMEL.match(member):
                    # ns::inner::Type: a nested namespace, which the
                    # repairs declare with what is used of it (repair.py)
                    continue
                elif member or _CAMEL.match(name) or (
                        after and not name.isupper()):
                    members = types.setdefault(name, set())
                    if member and _member_ok(member):
                        members.add(member)
                elif re.match(r'^[A-Z][A-Z0-9_]+$', name):
                    constants.add(name)
                else:
                    objects.add(name)
        for name in templates:
            types.pop(name, None)
        objects -= set(types) | templates
        constants -= set(types) | templates
        if types or objects or constants:
            result[namespace] = (types, objects, constants)
    return result, own


def _merge_unknown(stub_dir, namespace, names):
    """Grow rsia_model/unknown/<namespace>.h by these declarations."""
    types, objects, constants = names
    path = os.path.join(stub_dir, UNKNOWN_DIR, namespace + '.h')
    old = _read_text(path) or ''
    if old.startswith(_STUB_MARKER):
        for match in re.finditer(r'^// type (\w+):([\w ]*)$', old, re.M):
            types.setdefault(match.group(1), set()).update(
                match.group(2).split())
        objects |= set(re.findall(r'^// object (\w+)$', old, re.M))
        constants |= set(re.findall(r'^// constant (\w+)$', old, re.M))
    objects -= set(types)
    constants -= set(types) | objects
    guard = f'RSIA_MODEL_UNKNOWN_{namespace}_H'
    lines = [
        f'{_STUB_MARKER} kind=unknown: namespace {namespace}',
        f'// what the analysed sources use of `{namespace}::` (from headers the',
        '// model mode does not have): catch-all declarations',
        f'#ifndef {guard}', f'#define {guard}', '',
        '#include <rsia_model/message.h>', '', f'namespace {namespace}', '{']
    for name in sorted(types):
        members = sorted(types[name])
        # a repair header (repair.py) may have declared it already
        lines += [f'// type {name}:' + ''.join(' ' + m for m in members),
                  f'#if !defined({name}) && '
                  f'!defined(RSIA_REPAIRED__{namespace}__{name})',
                  f'struct {name} : ::rsia_model::Unknown', '{',
                  '  using ::rsia_model::Unknown::Unknown;',
                  '  using ::rsia_model::Unknown::operator=;']
        for member in members:
            lines += [f'#ifndef {member}',
                      f'  static ::rsia_model::Any {member};', '#endif']
        lines += ['};', '#endif']
    for name in sorted(objects):
        lines += [f'// object {name}', f'#ifndef {name}',
                  f'extern ::rsia_model::Any {name};', '#endif']
    for i, name in enumerate(sorted(constants)):
        lines += [f'// constant {name}', f'#ifndef {name}',
                  f'constexpr int {name} = {i + 1};', '#endif']
    lines += ['', f'}}  // namespace {namespace}', '', f'#endif  // {guard}', '']
    content = '\n'.join(lines)
    if content != old:
        write_atomically(path, content)


def _printable(text):
    return text.encode('ascii', 'replace').decode('ascii')


def _stand_ins_for(include, codes):
    """{include name: content} of the stand-in(s) for one include."""
    parts = include.split('/')
    if len(parts) == 3 and parts[1] in _ROS2_INTERFACE_DIRS and \
            parts[2].endswith('.hpp') and _PACKAGE.match(parts[0]):
        return {include: _ros2_interface_stub(*parts, codes)}
    if len(parts) != 2 or not parts[1].endswith('.h'):
        return {include: _empty_stub(include)}
    package, name = parts[0], parts[1][:-2]
    # messages are CamelCase, with exceptions (tf/tfMessage.h): a header
    # whose stem the sources name as `package::stem` is one too
    named = _IDENTIFIER.match(name) and any(
        re.search(r'\b' + package + r'\s*::\s*' + name + r'\b', code)
        for code in codes)
    if not (_PACKAGE.match(package) and (_CAMEL.match(name) or named)):
        return {include: _empty_stub(include)}
    for suffix, member in (('ActionGoal', 'goal'), ('ActionResult', 'result'),
                           ('ActionFeedback', 'feedback')):
        if name.endswith(suffix) and len(name) > len(suffix):
            base = name[:-len(suffix)]
            inner = base + suffix[len('Action'):]
            stubs = _stand_ins_for(f'{package}/{inner}.h', codes)
            stubs[include] = _message_stub(
                package, name, includes=[f'{package}/{inner}.h'],
                typedefs=[(f'_{member}_type', f'{inner}_<ContainerAllocator>')])
            return stubs
    if name.endswith('Action') and len(name) > len('Action'):
        base = name[:-len('Action')]
        stubs = {}
        typedefs = []
        includes = []
        for part, member in (('Goal', 'goal'), ('Result', 'result'),
                             ('Feedback', 'feedback')):
            sub = f'{package}/{base}Action{part}.h'
            stubs.update(_stand_ins_for(sub, codes))
            includes.append(sub)
            typedefs.append((f'_action_{member}_type',
                             f'{base}Action{part}_<ContainerAllocator>'))
        stubs[include] = _message_stub(
            package, name, includes=includes, typedefs=typedefs)
        return stubs
    if name.endswith('Config') and len(name) > len('Config') and \
            not _message_evidence(name, codes):
        return {include: _config_stub(package, name)}
    if _service_evidence(name, codes) and \
            not name.endswith(('Request', 'Response')):
        stubs = {}
        for part in ('Request', 'Response'):
            stubs.update(_stand_ins_for(f'{package}/{name}{part}.h', codes))
        if _message_evidence(name, codes):
            stubs[include] = _combined_stub(package, name)
        else:
            stubs[include] = _service_stub(package, name)
        return stubs
    # nothing tells a message from a service used only generically
    # (`typename S::Request`): a message also names the would-be parts
    return {include: _message_stub(
        package, name,
        declarations=[
            'template <class ContainerAllocator>',
            f'struct {name}Request_;',
            'template <class ContainerAllocator>',
            f'struct {name}Response_;', ''],
        typedefs=[('Request', f'{name}Request_<ContainerAllocator>'),
                  ('Response', f'{name}Response_<ContainerAllocator>')])}


# ROS 2 interfaces: `<pkg/msg/laser_scan.hpp>` declares
# `pkg::msg::LaserScan_<ContainerAllocator>` and `pkg::msg::LaserScan`
_ROS2_INTERFACE_DIRS = frozenset({'msg', 'srv', 'action'})


def _snake_case(name):
    """The header stem rosidl gives a type: ``TFMessage`` -> ``tf_message``."""
    return re.sub(r'(?<=[a-z0-9])(?=[A-Z])|(?<=[A-Z])(?=[A-Z][a-z])', '_',
                  name).lower()


def _ros2_type_name(package, kind, file_stem, codes):
    """The CamelCase name a snake_case interface header declares."""
    wanted = file_stem.replace('_', '').lower()
    pattern = re.compile(
        r'\b' + re.escape(package) + r'\s*::\s*' + kind +
        r'\s*::\s*([A-Z]\w*)')
    for code in codes:
        for match in pattern.finditer(code):
            if match.group(1).lower() == wanted:
                return match.group(1)
    return ''.join(p[:1].upper() + p[1:] for p in file_stem.split('_'))


def _ros2_interface_stub(package, kind, file_name, codes):
    stem = file_name[:-len('.hpp')]
    if '__' in stem or not _PACKAGE.match(stem):
        return _empty_stub(f'{package}/{kind}/{file_name}')
    name = _ros2_type_name(package, kind, stem, codes)
    guard = f'RSIA_STUB_{package}_{kind}_{stem}_HPP'
    lines = [
        f'{_STUB_MARKER} kind=ros2_{kind}: <{package}/{kind}/{file_name}>',
        '// a ROS 2 interface the model mode cannot read: the name, template',
        '// shape and pointer aliases of a generated rosidl header, its fields',
        '// the catch-all rsia_model::Fields',
        f'#ifndef {guard}', f'#define {guard}', '',
        '#include <memory>', '#include <rsia_model/message.h>', '',
        f'namespace {package}', '{', f'namespace {kind}', '{', '']

    def struct(struct_name):
        return [
            'template <class ContainerAllocator>',
            f'struct {struct_name}_ : ::rsia_model::Fields',
            '{',
            f'  using Type = {struct_name}_<ContainerAllocator>;',
            f'  using SharedPtr = std::shared_ptr<{struct_name}_>;',
            f'  using ConstSharedPtr = std::shared_ptr<const {struct_name}_>;',
            f'  using UniquePtr = std::unique_ptr<{struct_name}_>;',
            f'  using ConstUniquePtr = std::unique_ptr<const {struct_name}_>;',
            f'  using WeakPtr = std::weak_ptr<{struct_name}_>;',
            '};',
            f'using {struct_name} = {struct_name}_<std::allocator<void>>;', '']
    if kind == 'msg':
        lines += struct(name)
    elif kind == 'srv':
        lines += struct(name + '_Request') + struct(name + '_Response')
        lines += [f'struct {name}', '{',
                  f'  using Request = {name}_Request;',
                  f'  using Response = {name}_Response;', '};', '']
    else:
        parts = ('Goal', 'Result', 'Feedback')
        for part in parts:
            lines += struct(f'{name}_{part}')
        lines += [f'struct {name}', '{']
        lines += [f'  using {part} = {name}_{part};' for part in parts]
        lines += ['};', '']
    lines += [f'}}  // namespace {kind}', f'}}  // namespace {package}', '',
              f'#endif  // {guard}', '']
    return '\n'.join(lines)


def _guard(package, name):
    return f'RSIA_STUB_{package}_{name}_H'


def _message_stub(package, name, *, includes=(), typedefs=(), kind='message',
                  declarations=()):
    lines = [
        f'{_STUB_MARKER} kind={kind}: <{package}/{name}.h>',
        '// a message the model mode cannot read: its name, template shape and',
        '// pointer typedefs are those of a generated message header, its',
        '// fields the catch-all rsia_model::Fields',
        f'#ifndef {_guard(package, name)}',
        f'#define {_guard(package, name)}',
        '',
        '#include <rsia_model/message.h>']
    lines += [f'#include <{i}>' for i in includes]
    lines += ['', f'namespace {package}', '{', '']
    lines += list(declarations)
    lines += [
        'template <class ContainerAllocator>',
        f'struct {name}_ : ::rsia_model::Fields',
        '{',
        f'  typedef {name}_<ContainerAllocator> Type;']
    lines += [f'  typedef {target} {alias};' for alias, target in typedefs]
    lines += [
        f'  typedef boost::shared_ptr<{name}_<ContainerAllocator>> Ptr;',
        f'  typedef boost::shared_ptr<{name}_<ContainerAllocator> const> '
        'ConstPtr;',
        '};',
        '',
        f'typedef ::{package}::{name}_<std::allocator<void>> {name};',
        f'typedef boost::shared_ptr< ::{package}::{name}> {name}Ptr;',
        f'typedef boost::shared_ptr< ::{package}::{name} const> '
        f'{name}ConstPtr;',
        '',
        f'}}  // namespace {package}',
        '',
        f'#endif  // {_guard(package, name)}',
        '']
    return '\n'.join(lines)


def _service_stub(package, name):
    return '\n'.join([
        f'{_STUB_MARKER} kind=service: <{package}/{name}.h>',
        '// a service the model mode cannot read (the sources use its Request',
        '// or Response): the struct of a generated service header',
        f'#ifndef {_guard(package, name)}',
        f'#define {_guard(package, name)}',
        '',
        f'#include <{package}/{name}Request.h>',
        f'#include <{package}/{name}Response.h>',
        '',
        f'namespace {package}',
        '{',
        '',
        f'struct {name}',
        '{',
        f'  typedef {name}Request Request;',
        f'  typedef {name}Response Response;',
        '  Request request;',
        '  Response response;',
        '  typedef Request RequestType;',
        '  typedef Response ResponseType;',
        '};',
        '',
        f'}}  // namespace {package}',
        '',
        f'#endif  // {_guard(package, name)}',
        ''])


def _combined_stub(package, name):
    """A name used both as a message and as a service: serve both."""
    return _message_stub(
        package, name, kind='service_message',
        includes=[f'{package}/{name}Request.h', f'{package}/{name}Response.h'],
        typedefs=[('Request', f'::{package}::{name}Request'),
                  ('Response', f'::{package}::{name}Response'),
                  ('RequestType', f'::{package}::{name}Request'),
                  ('ResponseType', f'::{package}::{name}Response')])


def _combined_stub_from(content):
    match = re.search(r'<(\w+)/(\w+)\.h>', content.split('\n', 1)[0])
    return _combined_stub(match.group(1), match.group(2)) if match \
        else content


def _config_stub(package, name):
    return '\n'.join([
        f'{_STUB_MARKER} kind=config: <{package}/{name}.h>',
        '// a dynamic_reconfigure config (generated from a .cfg file): its',
        '// parameters are the catch-all rsia_model::Fields',
        f'#ifndef {_guard(package, name)}',
        f'#define {_guard(package, name)}',
        '',
        '#include <rsia_model/message.h>',
        '',
        f'namespace {package}',
        '{',
        '',
        f'class {name} : public ::rsia_model::Fields',
        '{',
        'public:',
        f'  static const {name}& __getDefault__();',
        f'  static const {name}& __getMin__();',
        f'  static const {name}& __getMax__();',
        '};',
        '',
        f'}}  // namespace {package}',
        '',
        f'#endif  // {_guard(package, name)}',
        ''])
