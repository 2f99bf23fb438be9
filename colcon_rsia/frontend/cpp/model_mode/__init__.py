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

:func:`prepare_model_arguments` is the whole mode for one unit: the
arguments kept (:mod:`.arguments`), the include scan (:mod:`.include_scan`),
what the sources use (:mod:`.source_names`), the stand-ins written
(:mod:`.stubs`, their text in :mod:`.stand_ins`); :mod:`.recovery`
completes what clang's errors show missing.
"""


import os
import re

from colcon_rsia.frontend.cpp.model_mode.arguments import filter_arguments
from colcon_rsia.frontend.cpp.model_mode.arguments import is_inside
from colcon_rsia.frontend.cpp.model_mode.arguments import real_path
from colcon_rsia.frontend.cpp.model_mode.headers import MODEL_HEADERS_DIR
from colcon_rsia.frontend.cpp.model_mode.headers import MODEL_LIBRARIES
from colcon_rsia.frontend.cpp.model_mode.include_scan import FileCache
from colcon_rsia.frontend.cpp.model_mode.include_scan import Scanner
from colcon_rsia.frontend.cpp.model_mode.source_names import code_only
from colcon_rsia.frontend.cpp.model_mode.source_names import COMMENT_OR_STRING
from colcon_rsia.frontend.cpp.model_mode.source_names import export_macro_defines
from colcon_rsia.frontend.cpp.model_mode.source_names import override_defines
from colcon_rsia.frontend.cpp.model_mode.source_names import std_defines
from colcon_rsia.frontend.cpp.model_mode.stand_ins import namespace_key
from colcon_rsia.frontend.cpp.model_mode.stubs import write_atomically
from colcon_rsia.frontend.cpp.model_mode.stubs import write_stand_ins

_ASSERT_CALLED = re.compile(r'(?<![\w:.>])assert\s*\(')


def prepare_model_arguments(*, source, arguments, package_path,
                            workspace_package_dirs, stub_dir, directory=None,
                            files=None):
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
    :param files: an include_scan.FileCache shared by the units of the
      package (default: one for this unit)
    :rtype: list
    """
    files = files or FileCache()
    roots = [files.realpath(package_path)] + \
        [files.realpath(d) for d in workspace_package_dirs]
    stub_dir = os.path.abspath(stub_dir)
    if any(is_inside(real_path(stub_dir), root) for root in roots):
        raise ValueError(
            f"the stub directory '{stub_dir}' lies in a package's source "
            'directory; stand-ins are never written among the sources')
    kept, search = filter_arguments(arguments, roots, directory)
    # a built workspace's database names the other packages' installed
    # headers, outside the sources: their sources' include/ stand for them
    # (a wrapper's body is read there)
    for package_dir in workspace_package_dirs:
        include = os.path.join(files.realpath(package_dir), 'include')
        if files.isdir(include) and ('-I', include) not in search:
            kept += ['-I', include]
            search.append(('-I', include))
    # the workspace's own copy of a library the model stands for (a
    # ros2_control checkout has the real controller_interface/): the real
    # headers win there, the model everywhere else
    own_first = [(option, directory) for option, directory in search
                 if option != '-iquote' and any(
                     files.isdir(os.path.join(directory, top))
                     for top in MODEL_LIBRARIES)]
    scanner = Scanner(roots=roots, search=search, stub_dir=stub_dir,
                      before_model=[d for _, d in own_first], files=files)
    scanner.scan(os.path.abspath(source))
    # the sources as code: no comments, literals or include lines
    codes = [code_only(text) for text in scanner.user_texts]
    up_dirs, own, first = write_stand_ins(scanner, codes, stub_dir)
    result = [word for pair in own_first for word in pair] + \
        ['-I', MODEL_HEADERS_DIR] + kept + ['-I', stub_dir]
    result += std_defines(codes)
    if any(_ASSERT_CALLED.search(code) for code in codes):
        # C's `assert`, which the real headers of the libraries included
        # before its use bring (the model's include less)
        result += ['-include', 'cassert']
    result += export_macro_defines(codes)
    result += override_defines(codes)
    result += [f'-DRSIA_MODEL_OWN_{namespace_key(namespace)}'
               for namespace in own]
    # the model declares nothing constexpr: a constexpr function of the
    # package that compares a field could never be constant, an error
    # clang lets a warning flag turn off
    result.append('-Wno-invalid-constexpr')
    # a braced list narrows only through the catch-all's conversion to
    # double (`std::string{any}`, `Info{yaw, deg2rad(30)}`); the real
    # types do not narrow, and clang lets a warning flag turn the error off
    result.append('-Wno-c++11-narrowing')
    # a member the recovery adds to a model class takes C varargs (the
    # last choice of overload resolution, recovery/overlay.py); passing a
    # class object there is an error clang lets a warning flag turn off
    result.append('-Wno-non-pod-varargs')
    if scanner.ros2:
        # the headers ROS 1 and ROS 2 share by name (tf2_ros/*.h,
        # message_filters/*.h, ...) take their ROS 2 shape, whatever the
        # order of the unit's includes
        result.append('-DRSIA_MODEL_RCLCPP=1')
    for up_dir in up_dirs:
        result += ['-I', up_dir]
    for header in first:
        result += ['-include', header]
    return result


__all__ = [
    'COMMENT_OR_STRING', 'MODEL_HEADERS_DIR', 'prepare_model_arguments',
    'write_atomically',
]
