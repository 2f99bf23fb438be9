# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What the sources use that the stand-ins must declare.

The members and constants used on message objects, the ``*_msgs`` types
named, the costly standard headers needed and the export macros no header
defines, read from the sources' text (without comments and literals).
"""

import re

from colcon_rsia.frontend.cpp.model_mode.include_scan import INCLUDE

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
# the `->` of a trailing return type before a body, which is no member
# access (`[&]() -> QBrush {`, `auto f() const -> Pose {`)
_TRAILING_RETURN = re.compile(
    r'(\)\s*(?:(?:const|mutable|noexcept|override)\s*)*)->(?=\s*(?:::)?'
    r'[A-Za-z_][\w:]*(?:\s*<[^;{}()]*>)?[\s&*]*\{)')
# Members whose calls every library means the same way, with their result:
# declared as functions when no use takes them for a value (or reaches
# into their result: OpenCV's `image.size().width`). As catch-all
# members they would return a catch-all value, which ties between the
# overloads it converts to: `std::vector<double> v(other.size())` between
# the size and the copy constructors, `const char * p = s.c_str()` fails.
KNOWN_METHODS = {
    'size': 'std::size_t',
    'c_str': 'const char *',
    # Eigen's and OpenCV's matrices
    'rows': 'long',
    'cols': 'long',
}
_RESULT_MEMBER = re.compile(
    r'(?:\.|->)\s*([A-Za-z_]\w*)\s*\(\s*\)\s*(?:\.|->)')
# the same through a variable: `auto size = image.size();`, then
# `size.width`
_RESULT_VARIABLE = re.compile(
    r'\bauto\s*&{0,2}\s*([A-Za-z_]\w*)\s*=[^;]*?(?:\.|->)\s*'
    r'([A-Za-z_]\w*)\s*\(\s*\)\s*;')
# `Type::NAME`, also in the kName style (`ILogger::Severity::kINFO`), and
# of a lower-case scope (a generated header of constants only, read as a
# message: `distortion_models::PLUMB_BOB`)
_CONSTANT = re.compile(
    r'\b[A-Za-z_]\w*\s*::\s*([A-Z][A-Z0-9_]*|k[A-Z]\w*)\b')
# the type of a ROS 2 message field: DiagnosticStatus::_level_type
_FIELD_TYPE = re.compile(r'::\s*(_[a-z][a-z0-9_]*_type)\b')
_MSGS_TYPE = re.compile(r'\b([a-z][a-z0-9_]*_msgs)\s*::\s*([A-Z][A-Za-z0-9]*)\b')
# ROS 2: any package's interfaces live in its `msg`, `srv` and `action`
# namespaces (rosidl), whatever the package's name: builtin_interfaces,
# a driver's own messages
_ROS2_MSGS_TYPE = re.compile(
    r'\b([a-z][a-z0-9_]*)\s*::\s*(msg|srv|action)\s*::'
    r'\s*([A-Z][A-Za-z0-9]*)\b')
# the outermost name of a namespace the code opens: its own, never a
# message package's (`namespace can::msg {` of a hand-written library)
_OPENED_NAMESPACE = re.compile(r'\bnamespace\s+([A-Za-z_]\w*)\s*(?:\{|::)')
# classes of *_msgs packages the model headers declare: no messages
_NOT_MESSAGES = frozenset(
    ('PointCloud2Iterator', 'PointCloud2ConstIterator', 'PointCloud2Modifier'))
IDENTIFIER = re.compile(r'^[A-Za-z_]\w*$')
CAMEL = re.compile(r'^[A-Z][A-Za-z0-9]*$')
ALL_CAPS = re.compile(r'^[A-Z][A-Z0-9_]+$')
PACKAGE = re.compile(r'^[a-z][a-z0-9_]*$')

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
    Any AnyElement Fields begin end cbegin cend rbegin rend
    ContainerAllocator boost std ros
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


# visibility and export macros, defined by headers CMake generates into the
# build tree (or by ones the model lacks): FOO_PUBLIC class Bar
# at declaration level, before a name (`class FOO_PUBLIC Node`,
# `FOO_LOCAL void f();`): a value such as RMW_QOS_POLICY_DURABILITY_
# TRANSIENT_LOCAL (followed by `;`, `,` or `)`) is no export macro
_EXPORT_MACRO = re.compile(
    r'\b([A-Z][A-Z0-9_]*_(?:EXPORT|PUBLIC|LOCAL|IMPORT|API|PUBLIC_TYPE'
    r'|DECLSPEC|VISIBILITY))\b(?=\s+[A-Za-z_~])')


def export_macro_defines(codes):
    """``-DFOO_PUBLIC=`` for each export macro no scanned file defines."""
    used = set()
    defined = set()
    for code in codes:
        used.update(_EXPORT_MACRO.findall(code))
        defined.update(re.findall(r'^\s*#\s*define\s+(\w+)', code, re.M))
    return [f'-D{name}=' for name in sorted(used - defined)]


# `override` only checks a member function against its base classes: a
# program means the same without it. Against a base the model does not
# know (a catch-all class), it is an error of the model's making.
_OVERRIDE = re.compile(r'\boverride\b')
# what comes before the keyword: a declarator's `)`, its qualifiers
_BEFORE_OVERRIDE = re.compile(
    r'(?:\)|&|\bconst|\bvolatile|\bnoexcept|\bfinal)\s*\Z')


def override_defines(codes):
    """``-Doverride=`` where the sources use `override` as the keyword only.

    (A variable named `override` keeps it: the sources stay as written.)
    """
    uses = [(code, m.start()) for code in codes
            for m in _OVERRIDE.finditer(code)]
    if uses and all(_BEFORE_OVERRIDE.search(code, max(0, start - 40), start)
                    for code, start in uses):
        return ['-Doverride=']
    return []


def code_only(text):
    """The text without comments, literals and include lines."""
    return INCLUDE.sub(' ', COMMENT_OR_STRING.sub(' ', text))


def used_names(codes):
    """The names the stand-ins' catch-all members must have.

    :returns: (members, constants, field types, {pkg: {include}} of the
      message types (ROS 1: of *_msgs packages; ROS 2: every `pkg::msg::`,
      `::srv::` and `::action::` type but in namespaces the code opens),
      member templates, members used as values). The include is the
      message's header: ``std_msgs/Header.h`` (ROS 1) or
      ``std_msgs/msg/header.hpp`` (ROS 2).
    """
    members = set()
    constants = set()
    field_types = set()
    msgs_types = {}
    templates = set()
    values = set()
    opened = {m.group(1) for code in codes
              for m in _OPENED_NAMESPACE.finditer(code)}
    for code in codes:
        code = _TRAILING_RETURN.sub(r'\1  ', code)
        members.update(m.group(1) for m in _MEMBER.finditer(code))
        templates.update(m.group(1) for m in _TEMPLATE_MEMBER.finditer(code))
        values.update(m.group(1) for m in _VALUE_MEMBER.finditer(code))
        values.update(m.group(1) for m in _RESULT_MEMBER.finditer(code)
                      if m.group(1) in KNOWN_METHODS)
        values.update(
            m.group(2) for m in _RESULT_VARIABLE.finditer(code)
            if m.group(2) in KNOWN_METHODS and re.compile(
                r'\b' + m.group(1) + r'\s*(?:\.|->)\s*[A-Za-z_]').search(
                    code, m.end()))
        constants.update(m.group(1) for m in _CONSTANT.finditer(code))
        field_types.update(m.group(1) for m in _FIELD_TYPE.finditer(code))
        for m in _MSGS_TYPE.finditer(code):
            name = re.sub(r'(?:ConstPtr|Ptr)$', '', m.group(2))
            if name and name not in _NOT_MESSAGES:
                msgs_types.setdefault(m.group(1), set()).add(
                    f'{m.group(1)}/{name}.h')
        for m in _ROS2_MSGS_TYPE.finditer(code):
            package, kind, name = m.groups()
            if package in opened:
                continue
            msgs_types.setdefault(package, set()).add(
                f'{package}/{kind}/{snake_case(name)}.hpp')
    # an ALL_CAPS name is a message's constant, also where the code reads
    # it through an object (`filter.UNKNOWN` beside `Label::UNKNOWN`): a
    # static member takes both
    constants = {n for n in constants if member_ok(n)}
    members = {n for n in members if member_ok(n)} - {
        n for n in constants if ALL_CAPS.match(n)}
    constants -= members
    # a member function template, unless some use takes it for a value
    values &= members
    templates = {n for n in templates - values if n in members}
    return members - templates, constants, field_types - members, \
        msgs_types, templates, values


def std_defines(codes):
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


def member_ok(name):
    """Whether a name may be a member the stand-ins declare."""
    # names beginning with `__` or `_X` are reserved to the implementation
    return bool(IDENTIFIER.match(name)) and name not in _NOT_MEMBERS and \
        not name.lower().startswith('rsia') and \
        not re.match(r'_[_A-Z]', name)


def service_evidence(name, codes):
    """Whether the sources use `name` as a service (Request/Response)."""
    pattern = re.compile(
        r'\b' + re.escape(name) +
        r'(?:\s*::\s*(?:Request|Response)(?:Type)?\b|(?:Request|Response)\b)')
    return any(pattern.search(code) for code in codes)


def message_evidence(name, codes):
    """Whether the sources use `name` as a message (pointers to it)."""
    pattern = re.compile(
        r'\b' + re.escape(name) + r'(?:\s*::\s*(?:Const)?Ptr\b|(?:Const)?Ptr\b)')
    return any(pattern.search(code) for code in codes)


def snake_case(name):
    """The header stem rosidl gives a type: ``TFMessage`` -> ``tf_message``."""
    return re.sub(r'(?<=[a-z0-9])(?=[A-Z])|(?<=[A-Z])(?=[A-Z][a-z])', '_',
                  name).lower()


def template_kind(after, is_variable=None):
    """TEMPLATE, or TEMPLATE:<shape> when arguments of its use are values.

    The shape has a letter per argument of the use the line shows: 't' for
    a type, 'v' for a value, so that `Eigen::Matrix<double, 3, 1>` is
    declared with a type and two value parameters ('template:tvv').

    :param is_variable: whether the code declares a name as a variable:
      such an argument is a value (`Spline<double, 2, spline_dim>`)
    """
    arguments = template_arguments(after)
    shape = ''.join('v' if VALUE_ARGUMENT.search(a) or (
        is_variable and IDENTIFIER.match(a) and is_variable(a)) else 't'
        for a in arguments)
    return f'template:{shape}' if 'v' in shape else 'template'


# a template argument that is a value: a number, true/false, sizeof, an
# ALL_CAPS constant (not T or N alone: those name types as often), or
# arithmetic on names
VALUE_ARGUMENT = re.compile(
    r"^[-+]?\s*(?:\d[\w.']*|true|false|sizeof\b)|"
    r'^(?:\w+::)*[A-Z][A-Z0-9_]+$|'
    r'\w\s*[-+/%]\s*\w')


def end_of_template_arguments(text, start=0):
    """Where the template arguments that open at ``start`` end, or None.

    ``start`` is at their `<` (or at blanks before it); the result is past
    the matching `>`. None when no `<` opens there, or when a statement
    or a block ends first (`a < b;`).
    """
    depth = 0
    for position in range(start, min(len(text), start + 400)):
        char = text[position]
        if char == '<':
            depth += 1
        elif char == '>':
            depth -= 1
            if depth == 0:
                return position + 1
        elif char in ';{}' or (depth == 0 and not char.isspace()):
            return None
    return None


def template_arguments(after):
    """The arguments of `<...>` at the start of ``after`` (all on the line)."""
    if not after.startswith('<'):
        return []
    arguments, current, depth = [], [], 0
    for char in after[1:]:
        if depth == 0 and char in ',>':
            arguments.append(''.join(current).strip())
            current = []
            if char == '>':
                return arguments if all(arguments) else []
            continue
        if char in '<([{':
            depth += 1
        elif char in '>)]}':
            depth -= 1
        current.append(char)
    return []  # the list goes on past the line: shape unknown


def template_head(kind):
    """`template <...> ` for a TEMPLATE kind, by its shape."""
    shape = kind.partition(':')[2]
    if not shape:
        return 'template <class...> '
    # long long, not auto (C++17): ROS 1 code is compiled as C++14;
    # enumerators and bools convert to it
    parameters = ['class' if c == 't' else 'long long' for c in shape]
    parameters.append(parameters[-1] + '...')
    return f"template <{', '.join(parameters)}> "
