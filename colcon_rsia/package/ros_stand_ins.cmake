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
# generation targets).
function(target_link_libraries rsia_target)
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
    ament_environment_hooks ament_auto_find_build_dependencies
    ament_auto_find_test_dependencies ament_auto_package
    ament_auto_add_gtest autoware_package
    pluginlib_export_plugin_description_file
    rosidl_generate_interfaces rosidl_target_interfaces)
  cmake_language(EVAL CODE "function(${rsia_command})\nendfunction()")
endforeach()

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
