# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
#
# Included by colcon-rsia's own configure of an unbuilt package
# (CMAKE_PROJECT_TOP_LEVEL_INCLUDES, see colcon_rsia/package/cmake_configure.py)
# so that CMake itself says which executables the package makes although no
# ROS is installed: every find_package() succeeds with empty results, and the
# commands ROS packages bring (catkin, ament, rosidl, ...) do nothing, except
# those that make targets or register components.
#
# RSIA_RECORD_FILE (set on the command line) receives one line per component
# registration: "node<TAB>plugin<TAB>executable" or "nodes<TAB>class".

# -- no program of the package runs -----------------------------------------

# A configure only asks which targets the package makes. No program runs for
# that: the sandbox colcon-rsia configures in lets CMake start none (every
# execve fails, see colcon_rsia/package/no_exec.py), and the compilers are
# taken as given (CMAKE_<LANG>_COMPILER_FORCED). The commands that would start
# one start nothing here and report success with empty output, so that a
# package that checks their result still configures (one of autoware's
# pip-installs at configure time). Each is defined twice: CMake keeps a
# replaced command as `_<name>`, which then names the first replacement,
# never CMake's own command; CMake's own modules get the replacements too.
foreach(rsia_round 1 2)
  function(execute_process)
    rsia_nothing_run("OUTPUT_VARIABLE;ERROR_VARIABLE"
      "RESULT_VARIABLE;RESULTS_VARIABLE" ${ARGV})
  endfunction()
  function(exec_program rsia_program)
    rsia_nothing_run("OUTPUT_VARIABLE" "RETURN_VALUE" ${ARGN})
  endfunction()
  function(try_run rsia_run_result rsia_compile_result)
    set(${rsia_run_result} 0 PARENT_SCOPE)
    set(${rsia_compile_result} TRUE PARENT_SCOPE)
    rsia_nothing_run("COMPILE_OUTPUT_VARIABLE;RUN_OUTPUT_VARIABLE;OUTPUT_VARIABLE;RUN_OUTPUT_STDOUT_VARIABLE;RUN_OUTPUT_STDERR_VARIABLE"
      "" ${ARGN})
  endfunction()
  # nothing compiles (a check of a flag or a header finds it missing)
  function(try_compile rsia_result)
    set(${rsia_result} FALSE PARENT_SCOPE)
    rsia_nothing_run("OUTPUT_VARIABLE" "" ${ARGN})
  endfunction()
  # site_name() runs `hostname`
  function(site_name rsia_variable)
    set(${rsia_variable} "localhost" PARENT_SCOPE)
  endfunction()
  # loads a library into CMake (a policy of CMake 2 allows it)
  function(load_command)
    message(STATUS "colcon-rsia: load_command() of the package not run")
  endfunction()
endforeach()

# rsia_nothing_run(<output keywords> <result keywords> <arguments>), in a
# replacement's scope: the variables the arguments name after the output
# keywords are set empty, after the result keywords 0, in its caller's scope
macro(rsia_nothing_run rsia_outputs rsia_results)
  set(rsia_output_keywords "${rsia_outputs}")
  set(rsia_result_keywords "${rsia_results}")
  cmake_parse_arguments(rsia ""
    "${rsia_output_keywords};${rsia_result_keywords}" "" ${ARGN})
  foreach(rsia_keyword IN LISTS rsia_output_keywords rsia_result_keywords)
    if(NOT rsia_${rsia_keyword})
      continue()
    endif()
    # (list(FIND), not if(IN_LIST): a macro runs under its caller's
    # policies, and IN_LIST is an error below cmake_minimum_required 3.3,
    # as in most ROS 1 packages)
    list(FIND rsia_result_keywords "${rsia_keyword}" rsia_result_index)
    if(rsia_result_index GREATER -1)
      set(${rsia_${rsia_keyword}} 0 PARENT_SCOPE)
    else()
      set(${rsia_${rsia_keyword}} "" PARENT_SCOPE)
    endif()
  endforeach()
  message(STATUS "colcon-rsia: a program of the package not run")
endmacro()

# -- the compilers, taken as given ------------------------------------------

# No compiler was asked what it supports: it has every feature CMake knows
# (target_compile_features(node PUBLIC cxx_std_17) fails otherwise)
foreach(rsia_language C CXX)
  get_property(rsia_features GLOBAL PROPERTY
    CMAKE_${rsia_language}_KNOWN_FEATURES)
  set(CMAKE_${rsia_language}_COMPILE_FEATURES ${rsia_features})
endforeach()

# -- find_package: every package is found, with nothing in it --------------

macro(rsia_provide_package rsia_method rsia_package)
  set(${rsia_package}_FOUND TRUE)
  string(TOUPPER "${rsia_package}" rsia_upper)
  set(${rsia_upper}_FOUND TRUE)
  foreach(rsia_suffix INCLUDE_DIRS INCLUDE_DIR LIBRARIES LIBRARY LIBRARY_DIRS
      DEFINITIONS TARGETS EXPORTED_TARGETS INTERFACES)
    set(${rsia_package}_${rsia_suffix} "")
    set(${rsia_upper}_${rsia_suffix} "")
  endforeach()
  # `if(${rosidl_cmake_VERSION} VERSION_LESS 2.5.0)` needs a version: the
  # one asked for, else one newer than any
  if("${ARGV2}" MATCHES "^[0-9]+(\\.[0-9]+)*$")
    set(${rsia_package}_VERSION "${ARGV2}")
  else()
    set(${rsia_package}_VERSION 9999.0.0)
  endif()
  set(${rsia_upper}_VERSION "${${rsia_package}_VERSION}")
  # find_package(catkin REQUIRED COMPONENTS roscpp ...): each component too
  foreach(rsia_component ${ARGN})
    set(${rsia_package}_${rsia_component}_FOUND TRUE)
  endforeach()
  if(rsia_package STREQUAL "catkin")
    rsia_catkin_destinations()
  endif()
endmacro()

cmake_language(SET_DEPENDENCY_PROVIDER rsia_provide_package
  SUPPORTED_METHODS FIND_PACKAGE)

# -- links and dependencies on what is not there ---------------------------

# Imported targets of packages that are not installed (rclcpp::rclcpp,
# Boost::system) would fail the generate step: they are left out. So are
# dependencies on targets the stand-ins below do not make (message
# generation targets), and links of such targets (pybind11_add_module's).
function(target_link_libraries rsia_target)
  if(NOT TARGET "${rsia_target}")
    return()
  endif()
  set(rsia_items)
  foreach(rsia_item IN LISTS ARGN)
    if(rsia_item MATCHES "::" AND NOT TARGET "${rsia_item}")
      continue()
    endif()
    list(APPEND rsia_items "${rsia_item}")
  endforeach()
  _target_link_libraries(${rsia_target} ${rsia_items})
endfunction()

function(add_dependencies rsia_target)
  set(rsia_items)
  foreach(rsia_item IN LISTS ARGN)
    if(TARGET "${rsia_item}")
      list(APPEND rsia_items "${rsia_item}")
    endif()
  endforeach()
  if(rsia_items)
    _add_dependencies(${rsia_target} ${rsia_items})
  endif()
endfunction()

# Nothing is installed, and the targets of stood-in commands are missing
function(install)
endfunction()

# Libraries and headers of packages that are not installed: found as nothing
# (a NOTFOUND result used by a target fails the generate step)
foreach(rsia_command find_library find_path find_file)
  cmake_language(EVAL CODE "
    function(${rsia_command} rsia_variable)
      set(rsia_arguments \${ARGN})
      list(REMOVE_ITEM rsia_arguments REQUIRED)
      _${rsia_command}(\${rsia_variable} \${rsia_arguments})
      if(NOT \${rsia_variable})
        set(\${rsia_variable} \"\" CACHE STRING \"\" FORCE)
      endif()
    endfunction()")
endforeach()

# -- catkin -----------------------------------------------------------------

macro(rsia_catkin_destinations)
  set(CATKIN_PACKAGE_BIN_DESTINATION lib/${PROJECT_NAME})
  set(CATKIN_PACKAGE_LIB_DESTINATION lib)
  set(CATKIN_PACKAGE_INCLUDE_DESTINATION include/${PROJECT_NAME})
  set(CATKIN_PACKAGE_SHARE_DESTINATION share/${PROJECT_NAME})
  set(CATKIN_PACKAGE_PYTHON_DESTINATION lib/python3/dist-packages/${PROJECT_NAME})
  set(CATKIN_PACKAGE_ETC_DESTINATION etc/${PROJECT_NAME})
  set(CATKIN_GLOBAL_BIN_DESTINATION bin)
  set(CATKIN_GLOBAL_LIB_DESTINATION lib)
  set(CATKIN_GLOBAL_LIBEXEC_DESTINATION lib)
  set(CATKIN_GLOBAL_INCLUDE_DESTINATION include)
  set(CATKIN_GLOBAL_SHARE_DESTINATION share)
  set(CATKIN_GLOBAL_ETC_DESTINATION etc)
  set(CATKIN_GLOBAL_PYTHON_DESTINATION lib/python3/dist-packages)
  set(CATKIN_DEVEL_PREFIX ${CMAKE_BINARY_DIR}/devel)
  set(CATKIN_ENABLE_TESTING OFF)
endmacro()

macro(catkin_package)
  rsia_catkin_destinations()
endmacro()

macro(catkin_destinations)
  rsia_catkin_destinations()
endmacro()

foreach(rsia_command catkin_python_setup catkin_install_python
    add_message_files add_service_files add_action_files generate_messages
    generate_dynamic_reconfigure_options catkin_add_gtest catkin_add_gmock
    catkin_add_nosetests add_rostest add_rostest_gtest
    roslaunch_add_file_check catkin_lint_cmake)
  cmake_language(EVAL CODE "function(${rsia_command})\nendfunction()")
endforeach()

# -- ament_cmake ------------------------------------------------------------

foreach(rsia_command ament_package ament_target_dependencies
    ament_export_dependencies ament_export_include_directories
    ament_export_libraries ament_export_targets ament_export_definitions
    ament_export_link_flags ament_export_interfaces
    ament_lint_auto_find_test_dependencies ament_add_gtest ament_add_gmock
    ament_add_gtest_executable ament_add_pytest_test ament_add_test
    ament_python_install_package ament_index_register_resource
    ament_environment_hooks ament_auto_find_test_dependencies
    ament_auto_package ament_auto_add_gtest
    pluginlib_export_plugin_description_file rosidl_target_interfaces)
  cmake_language(EVAL CODE "function(${rsia_command})\nendfunction()")
endforeach()

# ament_auto_find_build_dependencies() finds the build dependencies of
# package.xml (autoware_package() calls it): their variables are set (a
# package may test ${rosidl_cmake_VERSION})
macro(ament_auto_find_build_dependencies)
  set(rsia_lines)
  if(EXISTS "${PROJECT_SOURCE_DIR}/package.xml")
    file(STRINGS "${PROJECT_SOURCE_DIR}/package.xml" rsia_lines
      REGEX "<(depend|build_depend|buildtool_depend)>")
  endif()
  foreach(rsia_line IN LISTS rsia_lines)
    string(REGEX REPLACE ".*<[a-z_]+>[ \t]*([^< \t]+)[ \t]*</.*" "\\1"
      rsia_dependency "${rsia_line}")
    rsia_provide_package(FIND_PACKAGE "${rsia_dependency}")
  endforeach()
endmacro()

macro(autoware_package)
  ament_auto_find_build_dependencies()
endmacro()

# rosidl_default_generators brings rosidl_cmake, whose version packages test
macro(rosidl_generate_interfaces)
  if(NOT DEFINED rosidl_cmake_VERSION)
    rsia_provide_package(FIND_PACKAGE rosidl_cmake)
  endif()
endmacro()

# the variable it sets names no target we have: linking to nothing is right
function(rosidl_get_typesupport_target rsia_variable)
  set(${rsia_variable} "" PARENT_SCOPE)
endfunction()

# ament_auto_add_executable(name [options] [DIRECTORY dir] [sources...]):
# the sources are those given, and with DIRECTORY the C/C++ files under it
function(rsia_auto_sources rsia_variable)
  cmake_parse_arguments(rsia "WIN32;MACOSX_BUNDLE;EXCLUDE_FROM_ALL;NO_TARGET_LINK_LIBRARIES;STATIC;SHARED;MODULE;INTERFACE"
    "DIRECTORY" "" ${ARGN})
  set(rsia_sources ${rsia_UNPARSED_ARGUMENTS})
  if(rsia_DIRECTORY)
    file(GLOB_RECURSE rsia_found RELATIVE "${CMAKE_CURRENT_SOURCE_DIR}"
      "${rsia_DIRECTORY}/*.c" "${rsia_DIRECTORY}/*.cc"
      "${rsia_DIRECTORY}/*.cpp" "${rsia_DIRECTORY}/*.cxx")
    list(APPEND rsia_sources ${rsia_found})
  endif()
  set(${rsia_variable} ${rsia_sources} PARENT_SCOPE)
endfunction()

function(ament_auto_add_executable rsia_target)
  rsia_auto_sources(rsia_sources ${ARGN})
  add_executable(${rsia_target} ${rsia_sources})
endfunction()

function(ament_auto_add_library rsia_target)
  rsia_auto_sources(rsia_sources ${ARGN})
  if(rsia_sources)
    add_library(${rsia_target} ${rsia_sources})
  else()
    add_library(${rsia_target} INTERFACE)
  endif()
endfunction()

# generate_parameter_library(name parameters.yaml) makes a library others
# link to and install
function(generate_parameter_library rsia_target)
  add_library(${rsia_target} INTERFACE)
endfunction()

# -- rclcpp_components: recorded, for the components of the package ---------

function(rclcpp_components_register_node rsia_target)
  cmake_parse_arguments(rsia "" "PLUGIN;EXECUTABLE;EXECUTOR;RESOURCE_INDEX"
    "" ${ARGN})
  file(APPEND "${RSIA_RECORD_FILE}"
    "node\t${rsia_PLUGIN}\t${rsia_EXECUTABLE}\n")
endfunction()

function(rclcpp_components_register_nodes rsia_target)
  cmake_parse_arguments(rsia "" "RESOURCE_INDEX" "" ${ARGN})
  foreach(rsia_class IN LISTS rsia_UNPARSED_ARGUMENTS)
    file(APPEND "${RSIA_RECORD_FILE}" "nodes\t${rsia_class}\n")
  endforeach()
endfunction()

# -- the rest: commands the package calls that nothing defines -------------
# (RSIA_UNKNOWN_COMMANDS, found by scanning its CMake files, set by the caller)

foreach(rsia_command IN LISTS RSIA_UNKNOWN_COMMANDS)
  if(NOT COMMAND ${rsia_command})
    cmake_language(EVAL CODE "function(${rsia_command})\nendfunction()")
  endif()
endforeach()
