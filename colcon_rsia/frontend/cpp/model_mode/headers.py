# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Where the model headers are, and the libraries they stand for."""

import os
import threading

MODEL_HEADERS_DIR = os.path.join(
    os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
    'model_headers')


# namespaces never guessed from an unknown include directory: the model's own
# and those of messages
MODEL_NAMESPACES = frozenset(
    name for name in os.listdir(MODEL_HEADERS_DIR)
    if os.path.isdir(os.path.join(MODEL_HEADERS_DIR, name))) | {'std'}
# the libraries the model headers stand for (their include directories)
MODEL_LIBRARIES = sorted(MODEL_NAMESPACES - {'std', 'rsia_model'})


_texts = []
_lock = threading.Lock()


def model_header_texts():
    """[(relative path, text)] of every model header (read once).

    The indexes of what the model declares are made from them.
    """
    with _lock:
        if not _texts:
            for root, _, files in sorted(os.walk(MODEL_HEADERS_DIR)):
                for file in sorted(files):
                    path = os.path.join(root, file)
                    with open(path, encoding='utf-8', errors='replace') as h:
                        _texts.append(
                            (os.path.relpath(path, MODEL_HEADERS_DIR),
                             h.read()))
        return _texts
