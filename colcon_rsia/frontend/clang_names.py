# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
r"""File names that are not UTF-8, through libclang's Python binding.

Linux file names are bytes; Python gives the undecodable ones as surrogate
escapes (``caf\\udce9.cpp``). The binding encodes and decodes every string
as strict UTF-8, so one such name (a source, a header, an include
directory) failed the whole package. :func:`allow_undecodable_names` makes
it round-trip them with ``surrogateescape``: names go to libclang as the
bytes they are and come back as Python gives them; what is shown to
people is escaped later (:func:`colcon_rsia.safe_files.display`).
"""

import threading

import clang.cindex as ci

_LOCK = threading.Lock()


def _encode(text):
    if isinstance(text, bytes):
        return text
    return text.encode('utf-8', 'surrogateescape')


def _init(self, p=None):
    super(ci.c_char_p, self).__init__(_encode('' if p is None else p))


def _value(self):
    raw = super(ci.c_char_p, self).value
    return None if raw is None else raw.decode('utf-8', 'surrogateescape')


def allow_undecodable_names():
    """Patch the binding once (it is the only libclang user of the process)."""
    with _LOCK:
        if getattr(ci.c_interop_string, '_rsia_surrogates', False):
            return
        ci.c_interop_string.__init__ = _init
        ci.c_interop_string.value = property(_value)
        ci.b = _encode
        ci.c_interop_string._rsia_surrogates = True
