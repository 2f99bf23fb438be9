# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What a repair declares a name as, and the shapes of names."""

import re


ALL_CAPS = re.compile(r'^[A-Z][A-Z0-9_]*$')
CAMEL = re.compile(r'^_?[A-Z]')
LOWER_CAMEL = re.compile(r'^[a-z][a-z0-9]*[A-Z]\w*$')
# a C library's function or macro, its prefix apart
# (`PyUnicode_AsEncodedString`, `PyBytes_AS_STRING`, `SDL_GetTicks`):
# called, it is no class
C_FUNCTION = re.compile(r'^[A-Z][A-Za-z0-9]*_[A-Z]\w*$')
KEYWORDS = frozenset("""
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
# a member a model class lacks (`model-member:function`, `:type`,
# `:value`), added to the class for the unit's parse (overlay.py)
MODEL_MEMBER = 'model-member'
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
PRIORITY = (MACRO_FUNCTION, MACRO_VALUE, MACRO_VOID, MACRO_EMPTY,
            MACRO_CONDITION, VALUE, TEMPLATE, TYPE, NAMESPACE, SPECIALIZED,
            FUNCTION, CONSTANT, OBJECT)

# comments and literals, blanked before code is read for names
SOURCE_NOISE = re.compile(
    r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'',
    re.DOTALL)
_BRACE_OR_NAMESPACE = re.compile(r'\bnamespace\s*((?:\w|::)*)\s*\{|[{}]')


def opened_namespaces(code):
    """[name] of the named namespaces still open at the end of code."""
    opened = []  # a namespace's name, or '' for any other brace
    for match in _BRACE_OR_NAMESPACE.finditer(code):
        if match.group(0) == '}':
            if opened:
                opened.pop()
        else:
            opened.append(match.group(1) or '')
    return [name for name in opened if name]


def is_edit(kind):
    """Whether a repair's kind is an edit of the code (see edits.py)."""
    return kind.startswith('edit-')


def base_kind(kind):
    """A kind without its shape (`template:tv` is a `template`)."""
    return kind.partition(':')[0]


# the words before a name that do not make its line a declaration of it
_NOT_DECLARING = frozenset("""
    return case throw else delete new sizeof goto do co_return co_yield
    co_await typeid alignof decltype and or not""".split())


def declared_as_variable(name, texts):
    """Whether the code declares `name` (`Type name = ...`, `auto & name :`)."""
    pattern = re.compile(
        r'(\w+\s*[*&]+|\w+|(?<=[\w>])>)\s*\b' + re.escape(name) +
        r'\s*[=;({\[,):]')
    for text in texts:
        if name not in text:
            continue  # (no cleaning of a text that cannot declare it)
        for match in pattern.finditer(SOURCE_NOISE.sub(' ', text)):
            before = match.group(1)
            word = before.rstrip('*& \t\n')
            if before[-1] in '*&' and (word.endswith('_') or
                                       word[-1].isdigit()):
                continue  # `size_x_ * resolution_`: a product
            if word not in _NOT_DECLARING:
                return True
    return False


# a constant by Google's style: kMaxSize
K_CONSTANT = re.compile(r'^k[A-Z]')
