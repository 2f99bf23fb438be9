# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What the sources use of a C library whose header the model lacks.

C has no namespaces: a C library prefixes its names with its own
(`<pcap.h>`: `pcap_t`, `pcap_open_live`, `PCAP_ERRBUF_SIZE`; `<cuda.h>`:
`cudaStream_t`). For an unknown top-level include `<name.h>`, the global
names the sources use with that prefix are declared as catch-alls, as the
names used after `namespace::` of an unknown C++ library are.
"""

import re

from colcon_rsia.frontend.cpp.model_mode.source_names import ALL_CAPS
from colcon_rsia.frontend.cpp.model_mode.stand_ins import STUB_MARKER
from colcon_rsia.frontend.cpp.model_mode.unknown_headers import \
    catch_all_class
from colcon_rsia.frontend.cpp.model_mode.unknown_headers import \
    catch_all_function
from colcon_rsia.frontend.cpp.model_mode.unknown_headers import undeclared

# a prefix shorter than this says nothing (`<io.h>`: `io_service`)
_MIN_PREFIX = 3
_C_HEADER = re.compile(r'^([A-Za-z][A-Za-z0-9_]*)\.h$')
# a type in a declaration: `pcap_t * handle;`, `struct pcap_pkthdr *h`
_DECLARES = re.compile(r'\s*[*&]*\s*[A-Za-z_]\w*\s*[;=,)(\[]')
# a name the sources declare (`int pcap_count;`, `void pcap_log(...)`):
# after a type, not after `return` and the like
_DECLARED_AFTER = re.compile(
    r'\b(?!(?:return|else|case|new|delete|throw|sizeof|const|volatile|'
    r'static|extern|inline|mutable|constexpr|typedef|unsigned|signed|'
    r'struct|enum|union)\b)\w+[\s*&]+\Z')


def _prefixes(includes):
    """The name prefixes of the unknown top-level C headers included."""
    prefixes = set()
    for include in includes:
        match = _C_HEADER.match(include)
        if match is None:
            continue
        stem = match.group(1)
        for prefix in (stem, stem.split('_')[0]):
            if len(prefix) >= _MIN_PREFIX:
                prefixes.add(prefix.lower())
    return prefixes


def c_library_names(includes, codes, declared):
    """{name: kind} the sources use of unknown C libraries.

    kind: 'type', 'function', 'constant' or 'object'.

    :param includes: the unit's includes nothing provides
    :param declared: a function of the names the sources declare
      themselves
    """
    prefixes = _prefixes(includes)
    if not prefixes:
        return {}
    # the prefix, then `_` or a capital (`pcap_t`, `cudaMalloc`)
    used = re.compile(r'(?<![\w:.>~])((?i:' + '|'.join(
        sorted(map(re.escape, prefixes))) + r')(?:_|(?<=[a-z])[A-Z])\w*)')
    uses = [(code, match) for code in codes for match in used.finditer(code)]
    names, theirs = {}, set(declared())
    for code, match in uses:
        before = code[max(0, match.start() - 40):match.start()]
        if _DECLARED_AFTER.search(before):
            theirs.add(match.group(1))
    for code, match in uses:
        name = match.group(1)
        if name in theirs:
            continue
        after = code[match.end():match.end() + 80]
        before = code[max(0, match.start() - 8):match.start()]
        if ALL_CAPS.match(name):
            kind = 'constant'
        elif name.endswith('_t') or before.rstrip().endswith(
                ('struct', 'enum', 'union')) or _DECLARES.match(after):
            kind = 'type'
        elif re.match(r'\s*\(', after):
            kind = 'function'
        else:
            kind = 'object'
        # (a type wins over another use of the same name)
        if names.get(name) != 'type':
            names[name] = kind
    return names


def c_library_header(names):
    """The text of a header declaring these names globally."""
    lines = [f'{STUB_MARKER} kind=unknown: what the sources use of C '
             'libraries the model lacks', '#pragma once',
             '#include <rsia_model/message.h>']
    for i, (name, kind) in enumerate(sorted(names.items())):
        lines.append(undeclared(name))
        if kind == 'type':
            lines += catch_all_class(name)
        elif kind == 'function':
            lines += catch_all_function(name)
        elif kind == 'constant':
            lines.append(f'constexpr int {name} = {i + 1};')
        else:
            lines.append(f'extern ::rsia_model::Any {name};')
        lines.append('#endif')
    return '\n'.join(lines + [''])
