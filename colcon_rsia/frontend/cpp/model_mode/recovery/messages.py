# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The patterns the rules read: clang's messages and the code they show.

Each says what a diagnostic (or the line it points at) is about,
independent of any one library: an undeclared identifier, a member no
class has, a macro used as a statement.
"""

import re

UNDECLARED = re.compile(r"^use of undeclared identifier '(\w+)'")
# a name declared twice: the error's note points at the other declaration
# (a repair's class, then a header's typedef of the same name)
REDECLARED = re.compile(
    r'redefinition|conflicts with|redeclared|different kind')
UNKNOWN_TYPE = re.compile(r"^unknown type name '(\w+)'")
UNKNOWN_TEMPLATE = re.compile(
    r"^unknown template name '(\w+)'|^no template named '(\w+)'$")
# `QFont("Roboto", 10)` after `QFont::Bold` made QFont a namespace
NAMESPACE_AS_VALUE = re.compile(
    r"^unexpected namespace name '(\w+)': expected expression$")
IN_NAMESPACE = re.compile(
    r"^no (type|template|member|class) named '(\w+)' in namespace '([\w:]+)'")
NOT_NAMESPACE = re.compile(
    r"^use of undeclared identifier '(\w+)'|^expected namespace name")
IN_STD = re.compile(
    r"^no (?:type|template|member) named '(\w+)' in namespace "
    r"'std(?:::(?P<inner>\w+))?'")
# `std::ifstream f(path);` where only <iosfwd> came in on the way
UNDEFINED_IN_STD = re.compile(
    r"^implicit instantiation of undefined template 'std::(\w+)<")
# (of a class template's specialisation too: 'Eigen::Matrix<double, 3, 3>')
IN_CLASS = re.compile(r"^no member named '(\w+)' in '([\w:]+)(<.*>)?'$")
# (a field the catch-all base has, `type`, is no type)
TYPE_IN_CLASS = re.compile(
    r'^(?:no type named|typename specifier refers to non-type member) '
    r"'(\w+)' in '([\w:]+)(<.*>)?'$")
# the error of a value called (see MACRO_STATEMENT below)
CALLED_NON_FUNCTION = re.compile(
    r"^called object type '.*' is not a function or function pointer$")
# a name as the element type of an array among template arguments
ARRAY_TYPE_ARGUMENT = re.compile(
    r'[<,]\s*((?:::)?[A-Za-z_]\w*(?:::[A-Za-z_]\w*)*)\s*\[\s*$')
# a name reserved to the implementation, `__name__`, at an error: an
# attribute macro of a compiler we are not (and whether it takes arguments)
RESERVED_ATTRIBUTE = re.compile(r'(__[A-Za-z]\w*__)(?!\w)(\s*\()?')
INCOMPLETE = re.compile(
    r"incomplete type '[^']*' \(aka '(?:struct |class )?([\w:]+)'\)|"
    r'^(?:member access into|variable has|field has) incomplete type '
    r"'(?:struct |class )?([\w:]+)'$")
ARGUMENT_NOT_VALUE = re.compile(
    r"^'\w+' does not refer to a value|"
    r"^expected '\(' for function-style cast")
UNDEFINED_MACRO = re.compile(r"^function-like macro '(\w+)' is not defined")
# `template <> IdType customRegister(...)` of a library the model lacks
SPECIALIZATION = re.compile(
    r'^no function template matches function template specialization '
    r"'(\w+)'$")
# a call of a method no overload of which matches the arguments
NO_MATCHING_MEMBER = re.compile(
    r"^no matching member function for call to '(\w+)'$")
# `obj.elementsAs<T>()` of a member repaired as a value
NOT_A_TEMPLATE = re.compile(
    r"^'(\w+)' does not name a template but is followed by template "
    'arguments')
# `::gen::ParamListener` of a generated header: the scope is unknown
NOT_A_SCOPE = re.compile(
    r"^'(\w+)' is not a class, namespace, or enumeration$|"
    r"^no (member|type|template) named '(\w+)' in the global namespace$")
# a line that is a call of an ALL_CAPS name (with an underscore: not a
# class called FOO) and what clang says of it when the name is undefined
MACRO_STATEMENT = re.compile(r'^\s*([A-Z][A-Z0-9]*_[A-Z0-9_]*)\s*\(')
DECLARATION_EXPECTED = re.compile(
    r'^expected function body after function declarator$|'
    r'^(?:C\+\+ requires a type specifier|a type specifier is required) '
    r'for all declarations$')
OVERRIDE = re.compile(
    r"only virtual member functions can be marked '(?:override|final)'|"
    r"marked '(?:override|final)' but does not override")
NAMESPACE_ALIAS = re.compile(
    r'\bnamespace\s+\w+\s*=\s*(?:::)?([A-Za-z_][\w:]*)|'
    r'\busing\s+namespace\s+(?:::)?([A-Za-z_][\w:]*)')
# fmt's `"name"_a = value` without fmt: its literal operator
LITERAL_OPERATOR = re.compile('^no matching literal operator for call to '
                              r"'operator\"\"(\w+)'")
# `template <> struct hash<ns::Path>` of the package,
# for a class a repair declared hashable
HASH_REDEFINED = re.compile(r"^redefinition of 'hash<(?:::)?([\w:]+)>'$")
