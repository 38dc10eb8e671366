# Installation and the package config. After `cmake --install`, a consumer does
#   find_package(contactlab REQUIRED)   # with the prefix in CMAKE_PREFIX_PATH
#   target_link_libraries(app PRIVATE contactlab::core contactlab::linear)
# Layout under the prefix:
#   lib/libcontactlab_{core,formulations,linear,algorithms}.so, bin/contactlab
#   include/contactlab/{base,core,formulations,linear,algorithms}/**.hpp   (#include "core/mesh/Mesh.hpp")
#   lib/cmake/contactlab/contactlab{Config,ConfigVersion,Targets*}.cmake
#   lib/cmake/contactlab/ContactlabDependencies.cmake    (shared with the build, see there)
# tests/downstream checks all of it from ctest.
include(CMakePackageConfigHelpers)

set(CONTACTLAB_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/contactlab" CACHE STRING
  "Where contactlabConfig.cmake is installed (relative to the prefix)")
mark_as_advanced(CONTACTLAB_INSTALL_CMAKEDIR)

set(_contactlab_install_targets contactlab_base contactlab_core contactlab_formulations contactlab_linear
  contactlab_algorithms)
if(TARGET contactlab)
  list(APPEND _contactlab_install_targets contactlab)
endif()

# Relocatable RPATH: the top level sets the absolute ${CMAKE_INSTALL_FULL_LIBDIR}, which is wrong
# as soon as the prefix is chosen at install time (`cmake --install --prefix ...`, packaging):
# bin/contactlab would then miss libcontactlab_*.so. Point at the libraries relative to the
# installed file instead; the link-path entries (CMAKE_INSTALL_RPATH_USE_LINK_PATH) remain.
if(NOT IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}" AND NOT IS_ABSOLUTE "${CMAKE_INSTALL_BINDIR}")
  if(APPLE)
    set(_contactlab_origin "@loader_path")
  else()
    set(_contactlab_origin "$ORIGIN")
  endif()
  foreach(t IN LISTS _contactlab_install_targets)
    get_target_property(_type ${t} TYPE)
    if(_type STREQUAL "INTERFACE_LIBRARY")
      continue()  # contactlab_base: headers only, nothing to load
    endif()
    if(_type STREQUAL "EXECUTABLE")
      set(_dest "${CMAKE_INSTALL_BINDIR}")
    else()
      set(_dest "${CMAKE_INSTALL_LIBDIR}")
    endif()
    file(RELATIVE_PATH _rel "/prefix/${_dest}" "/prefix/${CMAKE_INSTALL_LIBDIR}")
    if(_rel STREQUAL "")
      set(_rpath "${_contactlab_origin}")
    else()
      set(_rpath "${_contactlab_origin}/${_rel}")
    endif()
    get_target_property(_old ${t} INSTALL_RPATH)
    if(_old)
      list(REMOVE_ITEM _old "${CMAKE_INSTALL_FULL_LIBDIR}")
      list(APPEND _rpath ${_old})
    endif()
    set_target_properties(${t} PROPERTIES INSTALL_RPATH "${_rpath}")
  endforeach()
endif()

# The public headers are C++17 (std::optional, ...): consumers of the exported targets get it.
target_compile_features(contactlab_base INTERFACE cxx_std_17)
target_compile_features(contactlab_core INTERFACE cxx_std_17)

install(TARGETS ${_contactlab_install_targets}
  EXPORT contactlabTargets
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})

# Public headers: every *.hpp of the modules, keeping its path relative to the source root
# (include/contactlab/core/mesh/Mesh.hpp), matching the INSTALL_INTERFACE include directory
# include/contactlab of the targets. install(DIRECTORY) globs at install time, so headers
# added later need no re-configure. Headers generated into the build tree (the targets also
# have ${PROJECT_BINARY_DIR} as include directory) are installed the same way.
foreach(dir base core formulations linear algorithms)
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/${dir}/"
    DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/contactlab/${dir}"
    FILES_MATCHING PATTERN "*.hpp")
  if(NOT PROJECT_BINARY_DIR STREQUAL PROJECT_SOURCE_DIR
     AND IS_DIRECTORY "${PROJECT_BINARY_DIR}/${dir}")
    install(DIRECTORY "${PROJECT_BINARY_DIR}/${dir}/"
      DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/contactlab/${dir}"
      FILES_MATCHING PATTERN "*.hpp"
      PATTERN "CMakeFiles" EXCLUDE)
  endif()
endforeach()

install(EXPORT contactlabTargets
  NAMESPACE contactlab::
  FILE contactlabTargets.cmake
  DESTINATION "${CONTACTLAB_INSTALL_CMAKEDIR}")

# Where the dependencies were found at build time: the config passes them as HINTS (searched
# after the consumer's CMAKE_PREFIX_PATH / <Name>_ROOT / <Name>_DIR, before the system paths).
set(_contactlab_hint_lines "")
foreach(pkg Tpetra Amesos2 Belos Ifpack2 MueLu VTK)
  string(APPEND _contactlab_hint_lines "set(_contactlab_hint_${pkg} \"${${pkg}_DIR}\")\n")
endforeach()
foreach(lib GMSH METIS MUMPS)
  get_filename_component(_libdir "${${lib}_LIBRARY}" DIRECTORY)
  set(_hints "${${lib}_INCLUDE_DIR}" "${_libdir}")
  string(APPEND _contactlab_hint_lines "set(_contactlab_hint_${lib} \"${_hints}\")\n")
endforeach()
set(CONTACTLAB_DEPENDENCY_HINTS "${_contactlab_hint_lines}")

configure_package_config_file(
  "${PROJECT_SOURCE_DIR}/cmake/contactlabConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/contactlabConfig.cmake"
  INSTALL_DESTINATION "${CONTACTLAB_INSTALL_CMAKEDIR}"
  NO_SET_AND_CHECK_MACRO)
write_basic_package_version_file(
  "${PROJECT_BINARY_DIR}/contactlabConfigVersion.cmake"
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY SameMajorVersion)
install(FILES
  "${PROJECT_BINARY_DIR}/contactlabConfig.cmake"
  "${PROJECT_BINARY_DIR}/contactlabConfigVersion.cmake"
  "${PROJECT_SOURCE_DIR}/cmake/ContactlabDependencies.cmake"
  DESTINATION "${CONTACTLAB_INSTALL_CMAKEDIR}")
