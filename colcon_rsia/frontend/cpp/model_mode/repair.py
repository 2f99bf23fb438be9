# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Self-completing model mode: declarations made up from clang's errors.

The model headers cover the ROS API; stand-ins cover the includes nothing
provides. Real packages still use names neither declares (``cv::Mat_``,
``CV_8UC1``, ``hardware_interface::...``, ``FMT_COMPILE(...)``, a base class
from a library the model lacks, which makes every ``override`` an error).
Every such error can hide a call we look for, so after a parse with errors
this module reads clang's diagnostics, declares what they say is missing in
a per-unit *repair header* (force-included, in the stub directory) and the
unit is parsed again, a bounded number of rounds.

The declarations are permissive: classes derive from
``rsia_model::Unknown`` (constructible from anything, with every member
name the sources use), objects and functions are of or return
``rsia_model::Any``. How a name is used decides what it becomes: the
characters after it on its line (``::`` a namespace, ``(`` a function or a
function-like macro, ``<`` a template).

A repair header only grows, and a unit whose sources did not change is
read from the cache: a package is repaired once.
"""

import hashlib
import os
import re
import threading

from colcon_rsia.frontend.cpp.model_mode.headers import MODEL_HEADERS_DIR
from colcon_rsia.frontend.cpp.model_mode.source_edits import is_edit
from colcon_rsia.frontend.cpp.model_mode.source_names import COMMENT_OR_STRING
from colcon_rsia.frontend.cpp.model_mode.source_names import \
    end_of_template_arguments
from colcon_rsia.frontend.cpp.model_mode.source_names import \
    template_arguments
from colcon_rsia.frontend.cpp.model_mode.source_names import template_head
from colcon_rsia.frontend.cpp.model_mode.source_names import template_kind
from colcon_rsia.frontend.cpp.model_mode.stubs import catch_all_class
from colcon_rsia.frontend.cpp.model_mode.stubs import catch_all_function
from colcon_rsia.frontend.cpp.model_mode.stubs import POINTER_TYPES
from colcon_rsia.frontend.cpp.model_mode.stubs import repaired_guard
from colcon_rsia.frontend.cpp.model_mode.stubs import same_class_as
from colcon_rsia.frontend.cpp.model_mode.stubs import UNKNOWN_DIR
from colcon_rsia.frontend.cpp.model_mode.stubs import write_atomically

# parses of a unit after the first: each round fixes what the previous one
# revealed (a namespace, then the names used in it, then an edit of a call
# the names made ambiguous, then the assignment of its result)
MAX_REPAIR_ROUNDS = 4

REPAIR_DIR = os.path.join('rsia_model', 'repair')
_MARKER = '// colcon-rsia repairs v1'

_UNDECLARED = re.compile(r"^use of undeclared identifier '(\w+)'")
_UNKNOWN_TYPE = re.compile(r"^unknown type name '(\w+)'")
_UNKNOWN_TEMPLATE = re.compile(
    r"^unknown template name '(\w+)'|^no template named '(\w+)'$")
# `QFont("Roboto", 10)` after `QFont::Bold` made QFont a namespace
_NAMESPACE_AS_VALUE = re.compile(
    r"^unexpected namespace name '(\w+)': expected expression$")
_IN_NAMESPACE = re.compile(
    r"^no (type|template|member|class) named '(\w+)' in namespace '([\w:]+)'")
_NOT_NAMESPACE = re.compile(
    r"^use of undeclared identifier '(\w+)'|^expected namespace name")
_IN_STD = re.compile(r"^no (?:type|template|member) named '(\w+)' in namespace 'std'")
# `std::ifstream f(path);` where only <iosfwd> came in on the way
_UNDEFINED_IN_STD = re.compile(
    r"^implicit instantiation of undefined template 'std::(\w+)<")
# (of a class template's specialisation too: 'Eigen::Matrix<double, 3, 3>')
_IN_CLASS = re.compile(r"^no member named '(\w+)' in '([\w:]+)(<.*>)?'$")
# (a field the catch-all base has, `type`, is no type)
_TYPE_IN_CLASS = re.compile(
    r'^(?:no type named|typename specifier refers to non-type member) '
    r"'(\w+)' in '([\w:]+)(<.*>)?'$")
# the error of a value called (see _MACRO_STATEMENT below)
_CALLED_NON_FUNCTION = re.compile(
    r"^called object type '.*' is not a function or function pointer$")
# a name as the element type of an array among template arguments
_ARRAY_TYPE_ARGUMENT = re.compile(
    r'[<,]\s*((?:::)?[A-Za-z_]\w*(?:::[A-Za-z_]\w*)*)\s*\[\s*$')
# a name reserved to the implementation, `__name__`, at an error: an
# attribute macro of a compiler we are not (and whether it takes arguments)
_RESERVED_ATTRIBUTE = re.compile(r'(__[A-Za-z]\w*__)(?!\w)(\s*\()?')
_INCOMPLETE = re.compile(
    r"incomplete type '[^']*' \(aka '(?:struct |class )?([\w:]+)'\)|"
    r'^(?:member access into|variable has|field has) incomplete type '
    r"'(?:struct |class )?([\w:]+)'$")
_ARGUMENT_NOT_VALUE = re.compile(
    r"^'\w+' does not refer to a value|"
    r"^expected '\(' for function-style cast")
_UNDEFINED_MACRO = re.compile(r"^function-like macro '(\w+)' is not defined")
# `template <> IdType customRegister(...)` of a library the model lacks
_SPECIALIZATION = re.compile(
    r'^no function template matches function template specialization '
    r"'(\w+)'$")
# `lanelet.regulatoryElementsAs<T>()` of a member repaired as a value
_NOT_A_TEMPLATE = re.compile(
    r"^'(\w+)' does not name a template but is followed by template "
    'arguments')
# `::gen::ParamListener` of a generated header: the scope is unknown
_NOT_A_SCOPE = re.compile(
    r"^'(\w+)' is not a class, namespace, or enumeration$|"
    r"^no (member|type|template) named '(\w+)' in the global namespace$")
# a line that is a call of an ALL_CAPS name (with an underscore: not a
# class called FOO) and what clang says of it when the name is undefined
_MACRO_STATEMENT = re.compile(r'^\s*([A-Z][A-Z0-9]*_[A-Z0-9_]*)\s*\(')
_DECLARATION_EXPECTED = re.compile(
    r'^expected function body after function declarator$|'
    r'^(?:C\+\+ requires a type specifier|a type specifier is required) '
    r'for all declarations$')
_OVERRIDE = re.compile(
    r"only virtual member functions can be marked '(?:override|final)'|"
    r"marked '(?:override|final)' but does not override")
_NAMESPACE_ALIAS = re.compile(
    r'\bnamespace\s+\w+\s*=\s*(?:::)?([A-Za-z_][\w:]*)|'
    r'\busing\s+namespace\s+(?:::)?([A-Za-z_][\w:]*)')
# fmt's `"name"_a = value` without fmt: its literal operator
_LITERAL = re.compile('^no matching literal operator for call to '
                      r"'operator\"\"(\w+)'")
# `template <> struct hash<lanelet::routing::LaneletPath>` of the package,
# for a class a repair declared hashable
_HASH_REDEFINED = re.compile(r"^redefinition of 'hash<(?:::)?([\w:]+)>'$")
_ALL_CAPS = re.compile(r'^[A-Z][A-Z0-9_]*$')
_CAMEL = re.compile(r'^_?[A-Z]')
_LOWER_CAMEL = re.compile(r'^[a-z][a-z0-9]*[A-Z]\w*$')
# a C library's function or macro, its prefix apart
# (`PyUnicode_AsEncodedString`, `PyBytes_AS_STRING`, `SDL_GetTicks`):
# called, it is no class
_C_FUNCTION = re.compile(r'^[A-Z][A-Za-z0-9]*_[A-Z]\w*$')
_KEYWORDS = frozenset("""
    alignas alignof asm auto bool break case catch char class const constexpr
    continue decltype default delete do double else enum explicit export
    extern false float for friend goto if inline int long mutable namespace
    new noexcept nullptr operator private protected public register return
    short signed sizeof static struct switch template this throw true try
    typedef typeid typename union unsigned using virtual void volatile while
    std rsia_model
""".split())

# what a name becomes
NAMESPACE = 'namespace'
TYPE = 'type'
TEMPLATE = 'template'
FUNCTION = 'function'
SPECIALIZED = 'specialized-function'  # a function the code specialises
OBJECT = 'object'
CONSTANT = 'constant'
# a constant where clang said the name used as one is no value: it wins
# over the class an earlier round made of it
VALUE = 'value'
MACRO_VALUE = 'macro-value'        # FOO(...) used as a value
MACRO_EMPTY = 'macro-empty'        # FOO_EXPORT at declaration level
MACRO_VOID = 'macro-void'          # FOO(...) at declaration level
# FOO(name, var) { ... } at declaration level: a function's head
# (pybind11's PYBIND11_MODULE(module, m), boost.python's module macro)
MACRO_FUNCTION = 'macro-function'
MACRO_CONDITION = 'macro-condition'  # #if FOO(...)
NO_OVERRIDE = 'no-override'        # `override` made a no-op
LITERAL = 'literal'                # a user-defined literal's suffix
# a class repaired without its std::hash (the package specialises it)
NO_HASH = 'no-hash'
MEMBER = 'member'                  # a static member of a type declared here
MEMBER_TYPE = 'member-type'        # a nested type of a type declared here
MEMBER_TEMPLATE = 'member-template'  # a member used with template arguments
# a nested type used as a scope (`RosTopicDisplay::RTDClass::onInitialize()`,
# rviz's typedef of a base class by itself): the class itself, whose
# members the next round declares
MEMBER_SCOPE = 'member-scope'
MEMBER_KINDS = (MEMBER, MEMBER_TYPE, MEMBER_TEMPLATE, MEMBER_SCOPE)
# not a declaration: a name used with template arguments that one of the
# unit's member repairs declared without (see add_repairs)
TEMPLATE_USE = 'template-use'
STD_HEADER = 'std-header'          # a standard header to include
HEADER = 'header'                  # a model or stand-in header declaring it
# repairs that include a header rather than declare a name
INCLUDES = (STD_HEADER, HEADER)

# when one name is asked for as several kinds, the first of these wins
# (a name used as a type somewhere is a class, even where `Name::` made it
# look like a namespace: QFrame *line; QFrame::HLine)
_PRIORITY = (MACRO_FUNCTION, MACRO_VALUE, MACRO_VOID, MACRO_EMPTY,
             MACRO_CONDITION, VALUE, TEMPLATE, TYPE, NAMESPACE, SPECIALIZED,
             FUNCTION, CONSTANT, OBJECT)

# what a name of std:: needs (the model includes the costly ones only when
# the sources name them; a name reached otherwise is repaired here)
_STD_HEADER_OF = {
    name: header for header, names in {
        'algorithm': 'sort stable_sort find find_if count count_if copy '
                     'copy_if fill transform remove remove_if replace '
                     'reverse rotate unique min max minmax min_element '
                     'max_element clamp all_of any_of none_of for_each '
                     'lower_bound upper_bound binary_search equal search '
                     'partition nth_element',
        'cmath': 'sqrt cbrt hypot pow exp log log10 log2 sin cos tan asin '
                 'acos atan atan2 sinh cosh tanh fabs abs floor ceil round '
                 'lround trunc fmod remainder copysign isnan isinf isfinite '
                 'fmin fmax signbit',
        'numeric': 'accumulate iota inner_product partial_sum reduce gcd lcm '
                   'adjacent_difference transform_reduce',
        'memory': 'shared_ptr unique_ptr weak_ptr make_shared make_unique '
                  'enable_shared_from_this static_pointer_cast '
                  'dynamic_pointer_cast',
        'functional': 'function bind placeholders ref cref hash invoke '
                      'mem_fn reference_wrapper',
        'sstream': 'stringstream ostringstream istringstream '
                   'basic_stringstream basic_ostringstream '
                   'basic_istringstream',
        'iostream': 'cout cerr clog cin',
        'iomanip': 'setprecision setw setfill put_time quoted',
        'limits': 'numeric_limits',
        'mutex': 'mutex recursive_mutex timed_mutex lock_guard unique_lock '
                 'scoped_lock call_once once_flag',
        'shared_mutex': 'shared_mutex shared_lock',
        'condition_variable': 'condition_variable',
        'thread': 'thread this_thread',
        'atomic': 'atomic atomic_bool atomic_int',
        'chrono': 'chrono',
        'optional': 'optional nullopt make_optional',
        'variant': 'variant visit holds_alternative monostate',
        'tuple': 'tuple make_tuple tie get',
        'utility': 'pair make_pair move forward swap exchange',
        'map': 'map multimap',
        'unordered_map': 'unordered_map',
        'set': 'set multiset',
        'unordered_set': 'unordered_set',
        'list': 'list',
        'deque': 'deque',
        'queue': 'queue priority_queue',
        'stack': 'stack',
        'array': 'array',
        'string_view': 'string_view',
        'regex': 'regex regex_match regex_search regex_replace smatch',
        'random': 'mt19937 random_device uniform_real_distribution '
                  'uniform_int_distribution normal_distribution',
        'future': 'future promise async',
        'filesystem': 'filesystem',
        'fstream': 'ifstream ofstream fstream basic_ifstream '
                   'basic_ofstream basic_fstream',
        'iterator': 'back_inserter inserter distance advance next prev '
                    'begin end',
        'stdexcept': 'runtime_error logic_error invalid_argument '
                     'out_of_range',
        'cstring': 'memcpy memset strlen strcmp strncpy',
        'cstdlib': 'exit getenv abort',
        'complex': 'complex',
        'bitset': 'bitset',
        'numbers': 'numbers',
    }.items() for name in names.split()}


def repair_header(stub_dir, source):
    """The path of a unit's repair header (one per main file)."""
    digest = hashlib.sha1(os.path.abspath(source).encode(
        'utf-8', 'surrogateescape')).hexdigest()[:16]
    stem = re.sub(r'\W', '_', os.path.basename(source))[:40]
    return os.path.join(stub_dir, REPAIR_DIR, f'{stem}_{digest}.h')


def ensure_repair_header(path, source):
    """Create an empty repair header, so that it can be force-included."""
    if not os.path.isfile(path):
        write_atomically(path, _render({}, source))


def read_repairs(path):
    """{(kind, qualified name)} already declared in a repair header."""
    try:
        with open(path, encoding='utf-8') as h:
            text = h.read()
    except OSError:
        return set()
    return set(re.findall(r'^// repair (\S+) (\S+)$', text, re.MULTILINE))


def add_repairs(path, source, repairs):
    """Add declarations to a unit's repair header; return whether it grew."""
    known = read_repairs(path)
    # a member declared as a value and then used as `obj.name<T>()`, a
    # name as `name<T>(x)` after `using ns::name;`
    uses = {name for kind, name in repairs if kind == TEMPLATE_USE}
    templates = {MEMBER: MEMBER_TEMPLATE, OBJECT: FUNCTION}
    merged = _one_kind_each({
        (templates[kind], name)
        if kind in templates and name.rsplit('::', 1)[-1] in uses
        else (kind, name)
        for kind, name in known | repairs if kind != TEMPLATE_USE})
    if merged == known:
        return False
    write_atomically(path, _render(merged, source))
    return True


# what one unit needed that any unit of the package may need: qualified
# names, macros and standard headers (shared through this file, so that the
# units parsed later start with them and need fewer parses)
SHARED_REPAIRS = 'package.repairs'
_shared_lock = threading.Lock()


def _shareable(repair):
    kind, name = repair
    if is_edit(kind):
        return False  # a place in one file, which other units may not include
    # (a member of a qualified class: with its class, which is shared too)
    return kind in INCLUDES or kind.startswith('macro-') or (
        '::' in name and (kind not in MEMBER_KINDS or
                          '::' in name.rsplit('::', 1)[0]))


def share_repairs(header, repairs):
    """Offer a unit's repairs to the units of its package parsed later."""
    path = os.path.join(os.path.dirname(header), SHARED_REPAIRS)
    with _shared_lock:
        known = _read_shared(path)
        offered = {r for r in repairs if _shareable(r)}
        if not offered <= known:
            write_atomically(path, ''.join(
                f'{kind} {name}\n' for kind, name in sorted(known | offered)))


def seed_repairs(header, source, declared):
    """Start a unit's (empty) repair header with its package's repairs."""
    path = os.path.join(os.path.dirname(header), SHARED_REPAIRS)
    with _shared_lock:
        shared = _read_shared(path)
    # a unit may include the model header or the package header that
    # another unit lacked: only names declared in neither are seeded
    declared = set(declared) | model_declarations()
    seeds = {r for r in shared
             if r[0] in INCLUDES or not _declared(r[1], declared)}
    return bool(seeds) and add_repairs(header, source, seeds)


def _read_shared(path):
    try:
        with open(path, encoding='utf-8') as h:
            return {tuple(line.split(' ', 1)) for line in h.read().split('\n')
                    if ' ' in line}
    except OSError:
        return set()


def repairs_from_diagnostics(diagnostics, read_line, texts=(),
                             declared=frozenset(), stand_in=None):
    """{(kind, qualified name)} that would fix these errors.

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
    aliases = _aliases(texts)
    repairs = _unaliased(
        _repairs(diagnostics, read_line, stand_in, texts), aliases)
    for kind, name in list(repairs):
        if kind == NAMESPACE and name not in declared:
            repairs |= _uses_of_namespace(name, texts, aliases)
    return {_included(r, stand_in) for r in _one_kind_each({
        r for r in repairs
        if r[0] in INCLUDES or (
            (_reopened_namespace(r) or not _declared(r[1], declared)) and
            not any(part in _KEYWORDS for part in r[1].split('::')))})}


def _reopened_namespace(repair):
    """Whether a repair declares a lower-case namespace (harmless again).

    The package's own namespace (`autoware`) is undeclared where a header
    of a missing library names it first (`using
    autoware::kalman_filter::KalmanFilter;`); a class of the package is
    CamelCase, and stays the package's alone.
    """
    kind, name = repair
    return kind == NAMESPACE and not _CAMEL.match(name.split('::')[-1])


_ALIAS_DEFINITION = re.compile(
    r'\bnamespace\s+(\w+)\s*=\s*(?:::\s*)?([A-Za-z_]\w*(?:\s*::\s*\w+)*)\s*;')


def _aliases(texts):
    """{alias: namespace} of the `namespace bg = boost::geometry;` here."""
    return {match.group(1): re.sub(r'\s+', '', match.group(2))
            for text in texts for match in _ALIAS_DEFINITION.finditer(text)}


def _unaliased(repairs, aliases):
    """Repairs of `bg::distance` as of `boost::geometry::distance`.

    `namespace bg = boost::geometry;` fails while boost::geometry is
    missing, and then so does every `bg::` after it: declaring a namespace
    bg would clash with the alias once its target exists.
    """
    if not aliases:
        return repairs
    result = set()
    for kind, name in repairs:
        head, _, rest = name.partition('::')
        if head in aliases and kind not in INCLUDES and \
                not kind.startswith('macro-'):
            name = aliases[head] + ('::' + rest if rest else '')
            if not rest:
                # the alias itself names its target, a namespace (clang
                # takes `pt` of `pt::ptree tree;` for an unknown type)
                kind = NAMESPACE
        result.add((kind, name))
    return result


# namespaces of the compiler's support library, which real headers bring
# in on the way (cxxabi.h through the C++ runtime's)
_SYSTEM_NAMESPACE_HEADER = {'abi': 'cxxabi.h'}


def _included(repair, stand_in):
    """A name a model or stand-in header declares: include that header.

    A unit may use ``rclcpp::Duration`` or ``geometry_msgs::msg::Polygon``
    before it includes their header (through a header of an unknown
    library); a declaration of our own would then clash with the header's.
    """
    kind, name = repair
    if kind in INCLUDES or kind in MEMBER_KINDS + (TEMPLATE_USE,) or \
            kind.startswith('macro-') or kind in (NO_OVERRIDE, LITERAL,
                                                  NO_HASH):
        return repair
    system_header = _SYSTEM_NAMESPACE_HEADER.get(name.split('::')[0])
    if system_header:
        # abi::__cxa_demangle: the compiler's own header has it
        return (STD_HEADER, system_header)
    header = model_header_for(name)
    if header is None and stand_in is not None:
        # (a header no stand-in holds yet is written with the repair:
        # see analysis._write_stand_ins_of_repair)
        header = _interface_header(name)
    return (HEADER, header) if header else repair


_INTERFACE = re.compile(r'^(\w+)::(msg|srv|action)::([A-Z]\w*)$')


def _interface_header(name):
    """``pkg/msg/pose_stamped.hpp`` of ``pkg::msg::PoseStamped``."""
    match = _INTERFACE.match(name)
    if not match:
        return None
    package, kind, type_name = match.groups()
    # rosidl's file names: GPSFix -> gps_fix, PoseStamped -> pose_stamped
    snake = re.sub(r'(?<=[a-z0-9])(?=[A-Z])|(?<=[A-Z])(?=[A-Z][a-z])', '_',
                   type_name).lower()
    return f'{package}/{kind}/{snake}.hpp'


def _rank(kind):
    # a template with values in its shape beats one without: its first
    # declaration may have come from a use the line did not show whole
    return (_PRIORITY.index(_base_kind(kind)), ':' not in kind)


def _one_kind_each(repairs):
    """Keep one kind per name (a name both a type and an object is not).

    What was taken as declared inside a name that turns out a class
    becomes a member of that class.
    """
    chosen = {}
    for kind, name in sorted(repairs):
        if _base_kind(kind) not in _PRIORITY:
            chosen[(kind, name)] = (kind, name)
            continue
        current = chosen.get(name)
        if current is None or _rank(kind) < _rank(current[0]):
            chosen[name] = (kind, name)
    # `using ns::f;` (only a value to the line) and then `f(x)`, which
    # failed for it: ns::f is what the call needs, and a global f would
    # conflict with the using-declaration
    for kind, name in list(chosen.values()):
        short = name.rsplit('::', 1)[-1]
        used = chosen.get(short)
        if '::' in name and kind in (OBJECT, CONSTANT) and used and \
                used[0] in (FUNCTION, OBJECT, CONSTANT):
            chosen[name] = (used[0], name)
            del chosen[short]
        elif '::' in name and kind == FUNCTION and used and \
                used[0] == FUNCTION and \
                not _CAMEL.match(name.split('::')[-2]):
            # (also when ns::f is a function already: the global f made
            # before `using ns::f;` took effect conflicts with it; not
            # beside a class's `QObject::connect`, where the unqualified
            # `connect(...)` of a derived class needs its own)
            del chosen[short]
    classes = {name for kind, name in chosen.values()
               if _base_kind(kind) in (TYPE, TEMPLATE)}
    # a class the code also names qualified (`using ns::VehicleInfo;`, or a
    # `using namespace` seen before the namespace was declared) is that
    # class: a global one of the same name would make every use ambiguous
    qualified = {name.rsplit('::', 1)[1] for name in classes if '::' in name}
    # (and a member of it named through the short name is its member:
    # `Estimator::Direction` after `using ns::Estimator;`, unless the short
    # name was declared for itself: an rviz base class's method called
    # through its short name in a derived class resolves as repaired)
    full_name = {}
    for name in sorted(classes):
        if '::' in name:
            full_name.setdefault(name.rsplit('::', 1)[1], set()).add(name)
    result = set()
    for kind, name in chosen.values():
        owner = name.rsplit('::', 1)[0] if '::' in name else None
        if owner not in classes and owner not in chosen and \
                len(full_name.get(owner, ())) == 1:
            [owner] = full_name[owner]
            name = f'{owner}::{name.rsplit("::", 1)[1]}'
        if owner in classes and kind not in MEMBER_KINDS + INCLUDES:
            # (a scope inside a class, `Estimator::Direction::MAXIMIZE`,
            # is a nested type)
            kind = MEMBER_TYPE if _base_kind(kind) in (
                TYPE, TEMPLATE, NAMESPACE) else MEMBER
        elif any(name.startswith(c + '::') for c in classes if c != owner):
            continue  # deeper inside a class: not declarable from outside
        elif owner is None and name in qualified and \
                _base_kind(kind) in (TYPE, TEMPLATE):
            continue
        result.add((kind, name))
    # a member used as a type is a nested type, and one used as a scope
    # the class itself
    scopes = {name for kind, name in result if kind == MEMBER_SCOPE}
    return {(kind, name) for kind, name in result
            if kind == MEMBER_SCOPE or name not in scopes and (
                kind != MEMBER or (MEMBER_TYPE, name) not in result)}


def _declared(name, declared):
    """Whether the package declares this name (in its own namespace)."""
    *namespaces, short = name.split('::')
    if short not in declared:
        return False
    # tf2::Transform is missing even if karto::Transform exists, and
    # autoware::trajectory::Trajectory even if the package's own
    # `using Trajectory = ...` in namespace autoware does: only namespaces
    # the package opens itself may hold its declaration
    return all(namespace in declared for namespace in namespaces)


_DECLARATION = re.compile(
    r'\bnamespace\s+((?:\w+\s*::\s*)+\w+)\s*\{|'
    r'\b(?:class|struct|union|enum(?:\s+class)?|namespace)\s+'
    r'(?:\w+\s+)?(\w+)\s*(?:final\s*)?[:{]|'
    r'\busing\s+(\w+)\s*=|\btypedef\b[^;{}]*?\b(\w+)\s*;|'
    r'^\s*#\s*define\s+(\w+)', re.MULTILINE)


def declared_names(texts):
    """Names that classes, namespaces, aliases and macros of texts declare."""
    names = set()
    for text in texts:
        # `class X  // : public Base` then `{` on the next line
        code = COMMENT_OR_STRING.sub(' ', text)
        for match in _DECLARATION.finditer(code):
            if _aliases_namesake(code, match):
                continue
            # (each namespace of `namespace autoware::planning {`)
            names.update(part.strip() for g in match.groups() if g
                         for part in g.split('::'))
    return names


def _aliases_namesake(code, match):
    """Whether a declaration is an alias of its namesake elsewhere.

    `using PointCloud = pcl::PointCloud<P>;` and `typedef pcl::IndicesPtr
    IndicesPtr;` declare nothing of pcl's: pcl::PointCloud stays missing
    (and repairable) when the package opens a `namespace pcl` of its own.
    """
    alias, typedef = match.group(3), match.group(4)
    if alias:
        end = code.find(';', match.end())
        target = code[match.end():None if end < 0 else end]
        return re.search(r'::\s*' + alias + r'\b', target) is not None
    if typedef:
        return re.search(r'::\s*' + typedef + r'\b',
                         match.group(0)[:-1]) is not None
    return False


_file_declarations = {}


def file_declarations(path, text):
    """declared_names of one file, read once per content.

    Every repair round of every unit asks for the names of the package's
    headers it includes: the same headers, the same text, again and again.
    """
    key = (path, len(text), hash(text))
    found = _file_declarations.get(key)
    if found is None:
        found = frozenset(declared_names([text]))
        with _shared_lock:
            _file_declarations[key] = found
    return found


_model_texts = []


def _model_header_texts():
    """[(relative path, text)] of every model header (read once).

    Both indexes below are made from them.
    """
    with _shared_lock:
        if not _model_texts:
            for root, _, files in sorted(os.walk(MODEL_HEADERS_DIR)):
                for file in sorted(files):
                    path = os.path.join(root, file)
                    with open(path, encoding='utf-8', errors='replace') as h:
                        _model_texts.append(
                            (os.path.relpath(path, MODEL_HEADERS_DIR),
                             h.read()))
        return _model_texts


_model_declarations = []


def model_declarations():
    """The names the model headers declare (read once)."""
    texts = _model_header_texts()
    with _shared_lock:
        if not _model_declarations:
            _model_declarations.append(declared_names(
                text for _, text in texts))
        return _model_declarations[0]


_model_header_index = []
# a function at namespace level (`Logger get_logger(const std::string &);`):
# a repair of one of its calls includes the model header instead of
# declaring a catch-all the call would prefer
_FUNCTION_DECLARED = re.compile(
    r'^(?!return\b)(?:[A-Za-z_][\w:<>,]*(?:\s+[\w:<>,]+)*\s*[*&]*\s*)?'
    r'\b([a-z_]\w*)\s*\(', re.MULTILINE)
_NAMESPACE_OPENED = re.compile(r'\bnamespace\s+(\w+)\s*\{')


# `extern const std::string RGB8, RGBA8, ...;` at namespace level (its list
# may go on over indented lines)
_EXTERN_DECLARED = re.compile(r'^extern\s+[^;(){}]*;', re.MULTILINE)


def _extern_names(text):
    """The names of the variables the extern declarations of a text declare."""
    names = set()
    for match in _EXTERN_DECLARED.finditer(text):
        *_, first = match.group(0)[:-1].split(',')[0].split()
        names.update([first.lstrip('*&')] + [
            name.strip() for name in match.group(0)[:-1].split(',')[1:]])
    return names


_ENUM_BODY = re.compile(r'\benum\s+(?!class\b|struct\b)\w*\s*(?::[^{;]*)?\{([^}]*)\}')
_global_enumerators = []  # [{enumerator: model header}], read once


def _global_enumerator_header(name):
    """The model header whose global C enum has this enumerator, or None.

    `RCL_ROS_TIME` of rcl's `rcl_clock_type_t` (rclcpp/rclcpp.hpp), named
    before the unit includes the model: a constant of our own would clash
    with it.
    """
    texts = _model_header_texts()
    with _shared_lock:
        if not _global_enumerators:
            headers = {}
            for path, text in texts:
                code = _SOURCE_NOISE.sub(' ', text)
                for match in _ENUM_BODY.finditer(code):
                    if _opened_namespaces(code[:match.start()]):
                        continue
                    for enumerator in match.group(1).split(','):
                        word = enumerator.split('=')[0].strip()
                        if word:
                            headers.setdefault(word, path)
            _global_enumerators.append(headers)
        return _global_enumerators[0].get(name)


def model_header_for(name):
    """The model header (relative path) that declares a qualified name.

    One that opens the name's first namespace and declares its last part
    at namespace level (a class member of that name is another name);
    of several, the one in that namespace's directory, then the shortest.
    An unqualified name: the header of the global enum it is of.
    """
    *namespaces, short = name.split('::')
    if not namespaces:
        return _global_enumerator_header(short)
    texts = _model_header_texts()
    with _shared_lock:
        if not _model_header_index:
            for path, text in texts:
                # what a namespace declares: the model headers do not
                # indent namespace bodies, members are indented
                top_level = '\n'.join(
                    line for line in text.split('\n')
                    if line[:1] not in (' ', '\t'))
                _model_header_index.append((
                    path, set(_NAMESPACE_OPENED.findall(text)),
                    declared_names([top_level]) |
                    set(_FUNCTION_DECLARED.findall(top_level)) |
                    _extern_names(text)))
    found = [path for path, opened, names in _model_header_index
             if namespaces[0] in opened and short in names]
    if not found:
        return None
    return min(found, key=lambda p: (
        not p.startswith(namespaces[0] + '/'), len(p), p))


def _uses_of_namespace(namespace, texts, aliases=None, depth=0):
    """(kind, name) of what the texts use after ``namespace::``.

    Also after an alias of it (`bg::` for boost::geometry), and in the
    namespaces used inside it (`bg::model::d2::point_xy<double>`), each of
    which clang would report only once the one around it exists: a parse
    saved per level.
    """
    spellings = [namespace] + [
        alias + namespace[len(target):]
        for alias, target in (aliases or {}).items()
        if namespace == target or namespace.startswith(target + '::')]
    pattern = re.compile(
        '(?<![\\w:])(?:' + '|'.join(
            re.escape(spelling).replace('::', r'\s*::\s*')
            for spelling in spellings) +
        r')\s*::\s*(\w+)(?:\s*::\s*(\w+))?(?=(\s*[^\n]{0,200}))')
    found = set()
    inner = set()
    for text in texts:
        for match in pattern.finditer(text):
            name, member, after = match.groups()
            if name in _KEYWORDS or name == 'template':
                continue
            rest = after.lstrip()
            kind = _by_qualified_use(
                name, '::' if member else rest,
                text[max(0, match.start() - 200):match.start()], texts)
            if _base_kind(kind) == TEMPLATE and not member and \
                    rest.startswith('<'):
                # arguments that go on past the line (`rotate_transformer<`
                # then `bg::radian, double, 2, 2>`) still have a shape
                kind = _template_shape(' '.join(
                    text[match.start(3):match.start(3) + 400].split()), texts)
            found.add((kind, f'{namespace}::{name}'))
            if kind == NAMESPACE:
                inner.add(f'{namespace}::{name}')
            if member and kind == TYPE and member not in _KEYWORDS:
                nested = _by_use(member, rest, unqualified=False)[0] == TYPE \
                    and _names_nested_type(rest, text[
                        max(0, match.start() - 200):match.start()])
                # (`Converter::toImage<uint16_t, 1>(...)`: a template)
                found.add((
                    MEMBER_TYPE if nested else MEMBER_TEMPLATE
                    if re.match(r'<(?![<=])', rest) else MEMBER,
                    f'{namespace}::{name}::{member}'))
    if depth < 3:
        for name in sorted(inner):
            found |= _uses_of_namespace(name, texts, aliases, depth + 1)
    return found


def _names_nested_type(after, before):
    """Whether `Owner::Member`, between these, is a type of the class.

    So is one that declares a variable (`ns::Grid::Ptr grid`), one among
    template arguments (`std::optional<Buffer::Result>`) and one made of
    braces (`Trajectory<P>::Builder{}.build(points)`).
    """
    return bool(re.match(r'(?:[&*]\s*)?[A-Za-z_]|\{', after)) or (
        after.startswith(('>', ',')) and _in_template_arguments(before))


def _repairs(diagnostics, read_line, stand_in=None, texts=()):
    repairs = set()
    for message, file, line, column in diagnostics:
        text = read_line(file, line) if file else ''
        # the name the message is about, and the code that follows it
        quoted = _QUOTED_NAME.search(message)
        subject = quoted.group(1) if quoted else None
        if file and subject:
            text, column = _in_macro_arguments(
                read_line, file, line, text, column, subject)
        after = _after(text, column, subject) or \
            _next_line(read_line, file, line, text, subject)
        match = _RESERVED_ATTRIBUTE.match(text, max(0, column - 1))
        if match and (subject in (None, 'void', match.group(1))):
            # CUDA's `__device__`, `__host__`, `__launch_bounds__(256)`:
            # a compiler's attributes, read as a type or as a variable of
            # type void (`void __device__ f(...)`)
            repairs.add((MACRO_VOID if match.group(2) else MACRO_EMPTY,
                         match.group(1)))
            continue
        match = _UNDECLARED.match(message)
        if match:
            kind, name = _by_use(match.group(1), after, unqualified=True,
                                 texts=texts)
            if match.group(1) not in text and not _CAMEL.match(name):
                # spelled in a macro's body (THROW_ON_NULLPTR(p) expanding
                # to rcpputils::...): a namespace, by far the most common
                kind = NAMESPACE
            elif match.group(1) not in text and _ALL_CAPS.match(name) and \
                    any(re.search(r'\b' + name + r'\s*\(', t) for t in texts):
                # a macro a macro's body calls (REGISTER_ENTITY(...) in
                # the body of a workspace macro): a function-like macro
                kind = MACRO_VALUE
            elif kind == OBJECT and (
                    _CAST_TYPE.search(text[:max(0, column - 1)] + '@' + after)
                    or (text[:max(0, column - 1)].rstrip().endswith('<') and
                        after.startswith(('>', ',')))):
                # static_cast<uchar>(v), (uchar)v, Point3_<uchar>: a type
                # (OpenCV's uchar, brought in by `using namespace cv;`)
                kind = TYPE
            # an undeclared lower-case variable is most often a local or a
            # member whose declaration failed (an error of its own):
            # declaring a global of that name would only hide the cause.
            # One the code never declares is a library's (a C constant,
            # `flag = cudaHostAllocDefault`; an unknown base class's member,
            # `scene_manager_`)
            if kind != OBJECT or not _declared_as_variable(name, texts):
                repairs.add((kind, name))
            continue
        match = _UNKNOWN_TYPE.match(message)
        if match:
            name = _qualified(match.group(1), text, column)
            if _ALL_CAPS.match(name) and '_' in name:
                # FOO_EXPORT class X, BOOST_CLASS_EXPORT(X): macros of a
                # header the model lacks, at declaration level
                repairs.add((MACRO_VOID if after.startswith('(')
                             else MACRO_EMPTY, name))
            else:
                repairs.add((template_kind(after) if after.startswith('<')
                             else TYPE, name))
            continue
        match = _UNKNOWN_TEMPLATE.match(message)
        if match:
            repairs.add((template_kind(after), _qualified(
                match.group(1) or match.group(2), text, column)))
            continue
        match = _NAMESPACE_AS_VALUE.match(message)
        if match:
            # a class (its constants made it look like a namespace): the
            # names repaired inside it become its members
            repairs.add((TYPE, _qualified(match.group(1), text, column)))
            continue
        match = _IN_STD.match(message) or _UNDEFINED_IN_STD.match(message)
        if match:
            # a standard header the real headers would have brought in
            header = _STD_HEADER_OF.get(match.group(1))
            if header:
                repairs.add((STD_HEADER, header))
            continue
        match = _INCOMPLETE.search(message)
        if match:
            name = match.group(1) or match.group(2)
            if _ALL_CAPS.match(name) and '_' in name:
                # `struct EIGEN_ALIGN16 Point {`: an attribute's macro
                repairs.add((MACRO_EMPTY, name))
            else:
                # a class only forward-declared (its definition generated)
                repairs.add((TYPE, name))
            continue
        match = _IN_CLASS.match(message)
        if match:
            # a member of a class we declared (added only if we did)
            nested = _CAMEL.match(match.group(1)) and _names_nested_type(
                after, text[:max(0, column - 1)])
            kind = MEMBER_TYPE if nested else \
                MEMBER_TEMPLATE if after.startswith('<') else \
                MEMBER_SCOPE if after.startswith('::') and \
                _CAMEL.match(match.group(1)) else MEMBER
            repairs.add((kind, f'{match.group(2)}::{match.group(1)}'))
            repairs |= _unknown_owner(match, stand_in)
            continue
        match = _TYPE_IN_CLASS.match(message)
        if match:
            # pcl::PointCloud<P>::Ptr: a nested type, likewise; but a base
            # class's function called as a statement,
            # `ViewController::mimic(source_view);`, is read as a
            # declaration of `source_view` first: a lower-case name called
            # is a function
            called = after.startswith('(') and not _CAMEL.match(
                match.group(1))
            repairs.add((MEMBER if called else MEMBER_TYPE,
                         f'{match.group(2)}::{match.group(1)}'))
            repairs |= _unknown_owner(match, stand_in)
            continue
        match = _IN_NAMESPACE.match(message)
        if match:
            what, name, namespace = match.groups()
            if what == 'type' and after.startswith('(') and \
                    not _CAMEL.match(name):
                # `bg::correct(polygon);` read as a declaration of
                # `polygon`: a lower-case name called is a function
                kind = FUNCTION
            elif what in ('type', 'class', 'template') and \
                    after.startswith('<'):
                kind = _template_use(name, after, unqualified=False,
                                     texts=texts)
            elif what in ('type', 'class'):
                kind = TYPE
            elif what == 'template':
                kind = _template_shape(after, texts)
            else:
                kind = _by_qualified_use(name, after,
                                         text[:max(0, column - 1)], texts)
            repairs.add((kind, f'{namespace}::{name}'))
            continue
        match = _NOT_A_TEMPLATE.match(message)
        if match:
            repairs.add((TEMPLATE_USE, match.group(1)))
            continue
        match = _NOT_A_SCOPE.match(message)
        if match and (match.group(1) or after.startswith('::')):
            name = _qualified(match.group(1), text, column) \
                if match.group(1) else match.group(3)
            repairs.add((NAMESPACE, name))
            continue
        if match:
            # ::cudaFree(p), ::cudaError_t: a C library's global name
            what, name = match.group(2), match.group(3)
            kind = TYPE if what == 'type' else template_kind(after) \
                if what == 'template' else _by_use(
                    name, after, unqualified=False)[0]
            repairs.add((kind, name))
            continue
        match = _UNDEFINED_MACRO.match(message)
        if match:
            repairs.add((MACRO_CONDITION, match.group(1)))
            continue
        match = _SPECIALIZATION.match(message)
        if match:
            # the template is the namespace's the specialisation is in
            namespace = _namespace_at(read_line, file, line)
            repairs.add((SPECIALIZED, '::'.join(
                filter(None, (namespace, match.group(1))))))
            continue
        if message == 'expected class name':
            # `class Label : public QLabel` with QLabel undeclared: the
            # column is at the base's name
            match = re.match(r'\s*(?:::\s*)?([A-Za-z_]\w*(?:\s*::\s*[A-Za-z_]\w*)*)'
                             r'\s*(<?)', text[max(0, column - 1):])
            if match:
                # (clang's column is at the start of the name or at its
                # last part: `rviz_common::|ViewController`)
                name = _qualified(re.sub(r'\s+', '', match.group(1)), text,
                                  column)
                rest = text[max(0, column - 1) + match.start(2):]
                repairs.add((template_kind(rest) if match.group(2) else TYPE,
                             name))
            continue
        match = _MACRO_STATEMENT.match(text)
        if match and (message == 'expected unqualified-id' or
                      _DECLARATION_EXPECTED.match(message)) and \
                _opens_body(read_line, file, line, text, match.end()):
            repairs.add((MACRO_FUNCTION, match.group(1)))
            continue
        if match and _DECLARATION_EXPECTED.match(message):
            # BOOST_GEOMETRY_REGISTER_POINT_3D(...) at namespace level,
            # taken for a function declaration: a macro the model lacks
            repairs.add((MACRO_VOID, match.group(1)))
            continue
        if _OVERRIDE.search(message):
            repairs.add((NO_OVERRIDE, 'override'))
            continue
        match = _LITERAL.match(message) or _HASH_REDEFINED.match(message)
        if match:
            repairs.add((LITERAL if match.re is _LITERAL else NO_HASH,
                         match.group(1)))
            continue
        if _ARGUMENT_NOT_VALUE.match(message):
            # FOO_NVP(Base) with FOO_NVP unknown: the macro's argument is a
            # type; the macro is what is missing
            before = text[:max(0, column - 1)]
            macro = re.search(r'\b([A-Z][A-Z0-9_]*)\s*\(\s*$', before)
            if macro:
                repairs.add((MACRO_VALUE, macro.group(1)))
            elif subject and message.startswith(f"'{subject}'"):
                # `setCursor(Rotate2D)`: an enumerator of an unknown base
                # class, which its CamelCase made a class of ours
                repairs.add((VALUE, _qualified(subject, text, column)))
            continue
        match = _MACRO_STATEMENT.match(text)
        if match and _CALLED_NON_FUNCTION.match(message) and \
                column > match.end():
            # BOOST_SCOPE_EXIT((&a)(&b)) { ... }: the arguments of an
            # unknown macro read as calls (clang then says nothing of the
            # macro's name itself)
            repairs.add((MACRO_VOID, match.group(1)))
            continue
        if message == 'expected expression' and \
                text[column - 1:column] == ']':
            match = _ARRAY_TYPE_ARGUMENT.search(text[:column - 1])
            if match:
                # `std::unique_ptr<nvmlProcessInfo_t[]>`: clang reads the
                # unknown name as a value, and `[]` wants an index
                repairs.add((TYPE, match.group(1)))
            continue
        if message.startswith('expected namespace name'):
            for match in _NAMESPACE_ALIAS.finditer(text):
                name = (match.group(1) or match.group(2)).rstrip(':')
                if name:
                    repairs.add((NAMESPACE, name))
    return repairs


def _unknown_owner(match, stand_in):
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


_SOURCE_NOISE = re.compile(
    r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'',
    re.DOTALL)
_BRACE_OR_NAMESPACE = re.compile(r'\bnamespace\s*((?:\w|::)*)\s*\{|[{}]')


def _namespace_at(read_line, file, line):
    """The named namespaces open at a line of a file (`a::b`), or ''."""
    return '::'.join(_opened_namespaces(_SOURCE_NOISE.sub(' ', '\n'.join(
        read_line(file, number) for number in range(1, line)))))


def _opened_namespaces(code):
    """[name] of the named namespaces still open at the end of code."""
    opened = []  # a namespace's name, or '' for any other brace
    for match in _BRACE_OR_NAMESPACE.finditer(code):
        if match.group(0) == '}':
            if opened:
                opened.pop()
        else:
            opened.append(match.group(1) or '')
    return [name for name in opened if name]


# the first quoted name of a message: 'cudaMemcpyHostToDevice' of "use of
# undeclared identifier 'cudaMemcpyHostToDevice'"
_QUOTED_NAME = re.compile(r"'(\w+)'")
# how many lines past its first the arguments of a macro's call may go on
_MACRO_CALL_LINES = 12


def _in_macro_arguments(read_line, file, line, text, column, name):
    """(text, column) of the line that spells the name a message is about.

    Of a name in the arguments of a macro's call, clang gives the line the
    call starts on: `CHECK_CUDA_ERROR(cudaMemcpy(` with the name on one of
    the lines that follow, inside the call's parentheses.
    """
    spelled = re.compile(r'\b' + name + r'\b')
    if spelled.search(text):
        return text, column
    depth = text[max(0, column - 1):].count('(') - \
        text[max(0, column - 1):].count(')')
    for number in range(line + 1, line + 1 + _MACRO_CALL_LINES):
        if depth <= 0:
            break
        following = read_line(file, number)
        found = spelled.search(following)
        if found:
            return following, found.start() + 1
        depth += following.count('(') - following.count(')')
    return text, column


def _qualified(name, text, column):
    """`ns::Name` when the line qualifies the name clang calls unknown."""
    before = text[:max(0, column - 1)]
    match = re.search(r'((?:[A-Za-z_]\w*\s*::\s*)+)$', before)
    if not match:
        return name
    scopes = re.sub(r'\s+', '', match.group(1)).split('::')[:-1]
    # (`public ::testing::Test`: a keyword before the global scope)
    while scopes and scopes[0] in _KEYWORDS and \
            scopes[0] not in ('std', 'rsia_model'):
        scopes.pop(0)
    return '::'.join(scopes + [name])


def _opens_body(read_line, file, line, text, start):
    """Whether a body in braces follows the call whose `(` ends at start.

    (The braces may open the next line, as clang-format puts a function's.)
    """
    depth = 1
    for position in range(start, len(text)):
        depth += {'(': 1, ')': -1}.get(text[position], 0)
        if depth == 0:
            rest = text[position + 1:].strip()
            if not rest and file:
                rest = read_line(file, line + 1).strip()
            return rest.startswith('{')
    return False


def _after(text, column, name):
    """What follows the name a message is about, on its line."""
    if not text or not name:
        return ''
    start = max(0, column - 1)
    found = text.find(name, start)
    if found < 0:
        found = text.find(name)
    if found < 0:
        return ''
    return text[found + len(name):].lstrip()


def _next_line(read_line, file, line, text, name):
    """What follows the name of a message that ends its line.

    `cond ? Qt::ForbiddenCursor` with `: Qt::ArrowCursor` below: what the
    next line starts with tells a value from a type as the rest of the
    name's own line would.
    """
    if not file or not name or not re.search(r'\b' + name + r'\s*$', text):
        return ''
    return read_line(file, line + 1).lstrip()


# a name (@) as the type of a cast: `static_cast<@>(`, `(@)value`
_CAST_TYPE = re.compile(r'_cast\s*<\s*@>|(?<![\w\])])\s*\(\s*@\)\s*[\w(]')
# what comes before `ns::name` in `std::pair<ns::name, ...>`
_FIRST_TEMPLATE_ARGUMENT = re.compile(r'\w<\s*(?:::\s*)?(?:\w+\s*::\s*)*$')
# what comes before `Name` in `using ns::Name;`: a CamelCase name a
# using-declaration brings in is a class far more often than an enumerator
_USING_DECLARATION = re.compile(r'\busing\s+(?:::\s*)?(?:\w+\s*::\s*)*$')


def _base_kind(kind):
    return kind.partition(':')[0]


# the words before a name that do not make its line a declaration of it
_NOT_DECLARING = frozenset("""
    return case throw else delete new sizeof goto do co_return co_yield
    co_await typeid alignof decltype and or not""".split())


def _declared_as_variable(name, texts):
    """Whether the code declares `name` (`Type name = ...`, `auto & name :`)."""
    pattern = re.compile(
        r'(\w+\s*[*&]+|\w+|(?<=[\w>])>)\s*\b' + re.escape(name) +
        r'\s*[=;({\[,):]')
    for text in texts:
        if name not in text:
            continue  # (no cleaning of a text that cannot declare it)
        for match in pattern.finditer(_SOURCE_NOISE.sub(' ', text)):
            before = match.group(1)
            word = before.rstrip('*& \t\n')
            if before[-1] in '*&' and (word.endswith('_') or
                                       word[-1].isdigit()):
                continue  # `size_x_ * resolution_`: a product
            if word not in _NOT_DECLARING:
                return True
    return False


# a constant by Google's style: kMaxSize
_K_CONSTANT = re.compile(r'^k[A-Z]')


def _by_qualified_use(name, after, before, texts=()):
    """The kind of ``ns::name`` from the code around it on its line."""
    kind = _by_use(name, after, unqualified=False, texts=texts)[0]
    if kind == CONSTANT and _CAMEL.match(name) and \
            _USING_DECLARATION.search(before):
        return TYPE
    if kind in (OBJECT, CONSTANT) and _FIRST_TEMPLATE_ARGUMENT.search(before):
        # std::pair<boost::uuids::uuid, T>: a first template argument is a
        # type far more often than a value
        return TYPE
    if kind == OBJECT and after.startswith(('>', ',')) and \
            _in_template_arguments(before) and not _K_CONSTANT.match(name):
        # model::point<double, 2, bg::cs::cartesian>: a lower-case name
        # among template arguments is a type (a tag), as template_kind
        # takes it; a value would be a constant (kSize, MAX_SIZE)
        return TYPE
    if kind == CONSTANT and after.startswith(',') and \
            _in_template_arguments(before):
        # Matrix<float, Eigen::Dynamic, 1>: the template's parameters were
        # made from its use, where a CamelCase name is a type (see
        # template_kind)
        return TYPE
    return kind


def _in_template_arguments(before):
    """Whether the code before a name leaves a `<` of a template open."""
    statement = re.split(r'[;{}]', before)[-1]
    statement = re.sub(r'<<|>>|->|<=|>=', ' ', statement)
    return statement.count('<') > statement.count('>')


_CALL = re.compile(r'\s*\(')


def _by_use(name, after, *, unqualified, texts=()):
    """(kind, name) of a name from what follows it."""
    if after.startswith('::'):
        # undeclared: a namespace (Eigen::, karto::); a class of the
        # package would be declared (and never repaired); qualified: by
        # convention namespaces are lower case, classes CamelCase
        if _CAMEL.match(name) and not _ALL_CAPS.match(name) and \
                not unqualified:
            return TYPE, name
        return NAMESPACE, name
    if after.startswith('('):
        if _ALL_CAPS.match(name) and unqualified:
            return MACRO_VALUE, name
        return (TYPE if _CAMEL.match(name) and not _ALL_CAPS.match(name)
                and not _C_FUNCTION.match(name) else FUNCTION), name
    if after.startswith('<') and not after.startswith(('<<', '<=')) and \
            not _compares(after):
        return _template_use(name, after, unqualified=unqualified,
                             texts=texts), name
    if _ALL_CAPS.match(name):
        return CONSTANT, name
    if _CAMEL.match(name) and not unqualified and \
            re.match(r'(?:\)|;|,|\||\+|-|=|\?|\]|\}|!|:(?!:)|&&\s*[!(])',
                     after):
        # a CamelCase value, where a value ends or an operator follows: an
        # enumerator (Qt::AlignCenter), a constant (lanelet::InvalId, as an
        # argument; a first template argument is a type, see
        # _by_qualified_use)
        return CONSTANT, name
    if _CAMEL.match(name) or re.match(r'(?:[&*]\s*)?[A-Za-z_]', after):
        # CamelCase elsewhere (`std::unique_ptr<bond::Bond>`), or a name
        # followed by a name (`ns::archive ar(...)`)
        return TYPE, name
    return OBJECT, name


def _compares(after):
    """Whether the `<` that starts ``after`` compares, opening no template.

    So it does when a `)` or `;` closes its level before any `>`
    (`bp::std_in < pipe)`, boost::process's redirection). A `>` that
    follows (`bp::std_in < p, bp::std_out > out)`) cannot be told from
    template arguments (`f(acme::Grid<T> a, int b)`): they are taken.
    """
    depth = 0
    for char in after[1:]:
        if char in '([{':
            depth += 1
        elif char in ')]}':
            if depth == 0:
                return True
            depth -= 1
        elif char == '>':
            return False
        elif char == ';':
            return True
    return False


# a standard container's template without arguments: itself an argument
# of a template's template parameter
_BARE_STD_TEMPLATE = re.compile(
    r'^(?:::)?std::(?:vector|list|deque|set|map|multiset|multimap|'
    r'unordered_set|unordered_map|basic_string)$')


def _template_shape(after, texts):
    """The template_kind of a use, with what the texts declare.

    A lower-case argument the texts declare a variable is a value
    (`Spline<double, 2, spline_dim>`), unless they declare it a type too
    (`using point_t = ...;`, which reads as a declaration of a variable).
    """
    return template_kind(
        after, is_variable=lambda argument: argument not in _KEYWORDS and
        argument[:1].islower() and _declared_as_variable(argument, texts)
        and argument not in declared_names(texts))


def _template_use(name, after, *, unqualified, texts=()):
    """The kind of a name its line follows with template arguments.

    :param texts: the code of the files with errors, where an argument may
      be declared a variable (a value, then)
    """
    end = end_of_template_arguments(after)
    called = end is not None and _CALL.match(after, end)
    # (arguments on the lines after: `convertToTrajectoryPoints<` ends it)
    kind = _template_shape(after, texts)
    if (unqualified and not _CAMEL.match(name) and called) or \
            (_LOWER_CAMEL.match(name) and (called or after.strip() == '<')) \
            or (called and not _CAMEL.match(name) and (':' in kind or any(
                _BARE_STD_TEMPLATE.match(a)
                for a in template_arguments(after)))):
        # qobject_cast<QPushButton *>(sender()), also qualified in
        # lowerCamelCase (motion_utils::convertToPath<P>(path)), with a
        # value among its arguments (bg::get<bg::min_corner, 0>(box)) or a
        # template (ranges::to<std::vector>()): a function template;
        # boost::optional<T>(x) is a class
        return FUNCTION
    return kind


# types of libraries the model lacks that are numbers: a loop counts with
# them (`for (Eigen::Index i = 0; i < n; ++i)`)
_NUMBER_TYPES = {
    'Eigen::Index': 'std::ptrdiff_t',
    'Eigen::DenseIndex': 'std::ptrdiff_t',
    # lanelet2's element ids, which code mixes with std::vector<int64_t>
    'lanelet::Id': 'std::int64_t',
}

# allocators of libraries the model lacks: a standard container takes only
# a real allocator (`std::vector<T, Eigen::aligned_allocator<T>>`)
_ALLOCATORS = frozenset({'Eigen::aligned_allocator'})


def _render(repairs, source):
    """The repair header holding these declarations."""
    lines = [
        f'{_MARKER} for {_printable(source)}',
        "// declarations clang said were missing (see colcon_rsia's repair.py)",
        '#pragma once', '#include <rsia_model/message.h>', '']
    constant_values = {}
    members = {}
    for kind, name in repairs:
        if kind in MEMBER_KINDS:
            owner, member = name.rsplit('::', 1)
            members.setdefault(owner, set()).add((kind, member))
    # OpenCV's X2i beside X, neither with members of its own: X
    plain_classes = {name for kind, name in repairs
                     if kind == TYPE and name not in members}
    same_classes = {name: same_class_as(name, plain_classes)
                    for name in plain_classes
                    if same_class_as(name, plain_classes)}
    for kind, name in sorted(repairs):
        lines.append(f'// repair {kind} {name}')
        *namespaces, short = name.split('::')
        trailer = ''  # after the declaration, outside its namespaces
        if kind in MEMBER_KINDS:
            continue  # in its type's declaration
        if is_edit(kind):
            continue  # made to the code in memory (see source_edits.py)
        if kind in INCLUDES:
            lines.append(f'#include <{name}>')
            continue
        if kind == NO_OVERRIDE:
            lines += ['#define override', '#define final']
            continue
        if kind == NO_HASH:
            continue  # (see TYPE below)
        if kind == LITERAL:
            # (a string's, an integer's and a floating literal's forms)
            lines += [f'::rsia_model::Any& operator""{short}({parameters});'
                      for parameters in ('const char*, unsigned long',
                                         'unsigned long long', 'long double')]
            continue
        if kind == MACRO_FUNCTION:
            # the head of a function of its own name, whose parameters are
            # the arguments after the first (`m` of PYBIND11_MODULE(name,
            # m), used in the body); __LINE__ tells two uses apart
            lines += [
                '#ifndef RSIA_MACRO_BODY', '#define RSIA_MACRO_BODY_(line) '
                'rsia_macro_body_##line',
                '#define RSIA_MACRO_BODY(line) RSIA_MACRO_BODY_(line)',
                '#endif', f'#ifndef {short}',
                f'#define {short}(first, ...) static void '
                'RSIA_MACRO_BODY(__LINE__)(::rsia_model::Any __VA_ARGS__)',
                '#endif']
            continue
        if kind.startswith('macro-'):
            definition = {
                MACRO_VALUE: f'{short}(...) (::rsia_model::any_value())',
                MACRO_VOID: f'{short}(...)', MACRO_EMPTY: short,
                MACRO_CONDITION: f'{short}(...) 1'}[kind]
            lines += [f'#ifndef {short}', f'#define {definition}', '#endif']
            continue
        if kind == NAMESPACE:
            namespaces, body = namespaces + [short], ''
        elif kind == TYPE and short.endswith('s') and \
                (TYPE, name[:-1]) in repairs and name not in members:
            # VirtualWalls beside VirtualWall, ConstLanelets beside
            # ConstLanelet: by the convention of ROS code (autoware,
            # lanelet2) a vector of them; as a class of its own, it would
            # differ from the `std::vector<VirtualWall>` other code writes
            body = f'using {short} = std::vector<{short[:-1]}>;'
        elif kind == TYPE and name in same_classes:
            body = f'using {short} = {same_classes[name].split("::")[-1]};'
        elif kind == TYPE and name in _NUMBER_TYPES:
            body = f'using {short} = {_NUMBER_TYPES[name]};'
        elif _base_kind(kind) == TEMPLATE and name in _ALLOCATORS:
            body = f'template <class RsiaT> using {short} = ' \
                'std::allocator<RsiaT>;'
        elif _base_kind(kind) in (TYPE, TEMPLATE):
            if kind == TYPE and (NO_HASH, name) not in repairs:
                # a key of std::unordered_map (boost::uuids::uuid)
                trailer = f' template <> struct std::hash<::{name}> : ' \
                    '::rsia_model::UnknownHash {};'
            body = _one_line(catch_all_class(
                short, head=template_head(kind) if kind != TYPE else '',
                members=[{
                    MEMBER: _member_value(
                        m, lambda: constant_values.setdefault(
                            f'{name}::{m}', len(constant_values) + 1)),
                    MEMBER_TYPE: f'using {m} = ::rsia_model::Unknown;',
                    MEMBER_SCOPE: f'using {m} = {short};',
                    MEMBER_TEMPLATE:
                        f'RSIA_MODEL_MEMBER_TEMPLATE(static, {m}, )',
                }[k] for k, m in sorted(members.get(name, ()))
                    if m not in POINTER_TYPES]))
        elif kind == FUNCTION:
            body = _one_line(catch_all_function(short))
        elif kind == SPECIALIZED:
            # beside the calls' catch-all, a template an explicit
            # specialisation matches: its return type and parameters are
            # deduced from the specialisation's (a call deduces no RsiaR,
            # and explicit template arguments all go to RsiaT)
            body = _one_line(catch_all_function(short) + [
                'template <class... RsiaT, class RsiaR, class... RsiaA>',
                f'RsiaR {short}(RsiaA...);'])
        elif kind in (CONSTANT, VALUE):
            value = constant_values.setdefault(name, len(constant_values) + 1)
            body = f'constexpr int {short} = {value};'
        else:
            body = f'extern ::rsia_model::Any {short};'
        opening = ' '.join(f'namespace {n} {{' for n in namespaces)
        closing = '}' * len(namespaces)
        # (a namespace's guard repeats its last name: it declares nothing
        # a stand-in could step aside for)
        guard = repaired_guard('::'.join(namespaces + [short]))
        lines += [f'#ifndef {short}', f'#define {guard}',
                  f'{opening} {body} {closing}{trailer}'.strip(), '#endif']
    lines.append('')
    return '\n'.join(lines)


def _member_value(member, value):
    """The declaration of a static member of a class a repair declared.

    A constant by its name (`kLEGACY_CALIBRATION`, `MAX_SIZE`: an
    enumerator of the real class, a `case` label) is a distinct int;
    any other a catch-all.
    """
    if _K_CONSTANT.match(member) or (_ALL_CAPS.match(member) and
                                     len(member) > 1):
        return f'static constexpr int {member} = {value()};'
    return f'static ::rsia_model::Any {member};'


def _one_line(lines):
    """A declaration of stubs.py's on the one line of its repair."""
    return ' '.join(line.strip() for line in lines)


def _printable(text):
    return text.encode('ascii', 'replace').decode('ascii')
