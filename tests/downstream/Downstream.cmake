# Steps of the downstream test (see CMakeLists.txt), run as
#   cmake -DSTEP=install|configure|build -D... -P Downstream.cmake
cmake_minimum_required(VERSION 3.20)

function(run)
  string(REPLACE ";" " " _line "${ARGN}")
  message(STATUS "Running: ${_line}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE _rc)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "failed (${_rc}): ${_line}")
  endif()
endfunction()

set(_config_args "")
if(CONFIG)
  set(_config_args --config "${CONFIG}")
endif()

if(STEP STREQUAL "install")
  # A fresh prefix each time, so no stale file from an earlier install hides a missing rule.
  file(REMOVE_RECURSE "${PREFIX}")
  run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}" ${_config_args})

  set(_cmakedir "${PREFIX}/${INSTALL_CMAKEDIR}")
  foreach(f
      "${_cmakedir}/contactlabConfig.cmake"
      "${_cmakedir}/contactlabConfigVersion.cmake"
      "${_cmakedir}/contactlabTargets.cmake"
      "${_cmakedir}/ContactlabDependencies.cmake"
      "${PREFIX}/${INSTALL_INCLUDEDIR}/contactlab/core/mesh/Mesh.hpp"
      "${PREFIX}/${INSTALL_INCLUDEDIR}/contactlab/core/mesh/ElementType.hpp"
      "${PREFIX}/${INSTALL_INCLUDEDIR}/contactlab/base/LinearAlgebra.hpp"
      "${PREFIX}/${INSTALL_INCLUDEDIR}/contactlab/linear/LinearSolver.hpp")
    if(NOT EXISTS "${f}")
      message(FATAL_ERROR "not installed: ${f}")
    endif()
  endforeach()
  # Every header of the modules is installed.
  foreach(dir base core formulations linear algorithms)
    file(GLOB_RECURSE _headers RELATIVE "${CONTACTLAB_SOURCE_DIR}" "${CONTACTLAB_SOURCE_DIR}/${dir}/*.hpp")
    foreach(h IN LISTS _headers)
      if(NOT EXISTS "${PREFIX}/${INSTALL_INCLUDEDIR}/contactlab/${h}")
        message(FATAL_ERROR "header not installed: ${h}")
      endif()
    endforeach()
  endforeach()
  # An installed header may only #include "..." headers that are installed too (not apps/,
  # tests/ or generated files left in the build tree).
  set(_incdir "${PREFIX}/${INSTALL_INCLUDEDIR}/contactlab")
  file(GLOB_RECURSE _installed RELATIVE "${_incdir}" "${_incdir}/*.hpp")
  foreach(h IN LISTS _installed)
    file(STRINGS "${_incdir}/${h}" _lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    foreach(line IN LISTS _lines)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" _inc "${line}")
      get_filename_component(_dir "${_incdir}/${h}" DIRECTORY)
      if(NOT EXISTS "${_incdir}/${_inc}" AND NOT EXISTS "${_dir}/${_inc}")
        message(FATAL_ERROR "installed ${h} includes \"${_inc}\", which is not installed")
      endif()
    endforeach()
  endforeach()
  # The installed package must not point back into the source or build tree.
  file(GLOB _exported "${_cmakedir}/*.cmake")
  foreach(f IN LISTS _exported)
    file(READ "${f}" _text)
    foreach(tree "${CONTACTLAB_SOURCE_DIR}" "${BUILD_DIR}")
      string(FIND "${_text}" "${tree}/" _pos)
      if(NOT _pos EQUAL -1)
        message(FATAL_ERROR "${f} refers to ${tree}")
      endif()
    endforeach()
  endforeach()

elseif(STEP STREQUAL "configure")
  file(REMOVE_RECURSE "${DOWNSTREAM_BUILD_DIR}")
  set(_args -S "${SOURCE_DIR}" -B "${DOWNSTREAM_BUILD_DIR}" -G "${GENERATOR}"
    "-DCMAKE_PREFIX_PATH=${PREFIX}"
    "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
  if(MAKE_PROGRAM)
    list(APPEND _args "-DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM}")
  endif()
  if(CXX_LAUNCHER)
    list(APPEND _args "-DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER}")
  endif()
  if(CONFIG)
    list(APPEND _args "-DCMAKE_BUILD_TYPE=${CONFIG}")
  endif()
  run("${CMAKE_COMMAND}" ${_args})

elseif(STEP STREQUAL "build")
  run("${CMAKE_COMMAND}" --build "${DOWNSTREAM_BUILD_DIR}" ${_config_args} --parallel 2)

else()
  message(FATAL_ERROR "Downstream.cmake: unknown STEP '${STEP}'")
endif()
