# Third-party dependencies, all from Debian 12 packages (cmake/debian-packages.txt).
# Each becomes an imported target so modules link only what they use.
#
# One definition, used twice:
#  - by the top-level CMakeLists.txt (include(ContactlabDependencies)): a missing dependency is
#    a fatal error;
#  - installed next to contactlabConfig.cmake, which includes it to re-create in the consumer's
#    project the contactlab::<Dep> targets (and the MPI::, VTK:: and trilinos_* targets behind
#    them) that the exported contactlab:: targets link to. There _contactlab_in_config is TRUE:
#    packages are looked up with find_dependency() (honouring QUIET/REQUIRED of
#    find_package(contactlab)) and a missing dependency sets contactlab_FOUND to FALSE with a
#    message and returns. contactlabConfig.cmake may set _contactlab_hint_<Name>: where <Name>
#    was found when contactlab was built, searched after the consumer's own settings.
# So: a third-party dependency of an installed library (even a PRIVATE one) is added here and
# nowhere else, and build-only things (test frameworks, tools, compile options) stay out.

if(_contactlab_in_config)
  include(CMakeFindDependencyMacro)
  set(_contactlab_required "")
else()
  set(_contactlab_required REQUIRED)
endif()

# _contactlab_find_package(<Name> [args...]): find_package(<Name> args... REQUIRED) in the build,
# find_dependency(<Name> args... [HINTS hint]) in the installed config.
macro(_contactlab_find_package _contactlab_name)
  if(_contactlab_in_config)
    if(_contactlab_hint_${_contactlab_name})
      find_dependency(${_contactlab_name} ${ARGN} HINTS "${_contactlab_hint_${_contactlab_name}}")
    else()
      find_dependency(${_contactlab_name} ${ARGN})
    endif()
  else()
    find_package(${_contactlab_name} ${ARGN} REQUIRED)
  endif()
endmacro()

if(_contactlab_in_config)
  # The installed targets need MPI::MPI_CXX only; asking for C too would fail in a consumer
  # project that does not enable the C language.
  _contactlab_find_package(MPI COMPONENTS CXX)
else()
  _contactlab_find_package(MPI COMPONENTS C CXX)
endif()
_contactlab_find_package(Tpetra)
_contactlab_find_package(Amesos2)
_contactlab_find_package(Belos)
_contactlab_find_package(Ifpack2)
_contactlab_find_package(MueLu)
_contactlab_find_package(NOX)
_contactlab_find_package(VTK 9 COMPONENTS CommonCore CommonDataModel IOXML)
# Scenes are YAML 1.2, read by yaml-cpp (core/io/YamlParameterList). Debian: libyaml-cpp-dev.
_contactlab_find_package(yaml-cpp)

foreach(pkg Tpetra Amesos2 Belos Ifpack2 MueLu NOX)
  if(NOT TARGET contactlab::${pkg})
    add_library(contactlab::${pkg} INTERFACE IMPORTED)
    set_target_properties(contactlab::${pkg} PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${${pkg}_INCLUDE_DIRS};${${pkg}_TPL_INCLUDE_DIRS}"
      INTERFACE_LINK_LIBRARIES "${${pkg}_LIBRARIES};${${pkg}_TPL_LIBRARIES}"
      INTERFACE_LINK_DIRECTORIES "${${pkg}_LIBRARY_DIRS}")
  endif()
endforeach()

find_path(GMSH_INCLUDE_DIR gmsh.h HINTS ${_contactlab_hint_GMSH} ${_contactlab_required})
find_library(GMSH_LIBRARY gmsh HINTS ${_contactlab_hint_GMSH} ${_contactlab_required})
find_path(METIS_INCLUDE_DIR metis.h HINTS ${_contactlab_hint_METIS} ${_contactlab_required})
find_library(METIS_LIBRARY metis HINTS ${_contactlab_hint_METIS} ${_contactlab_required})
# HDF5 for the checkpoints (core/io/Hdf5Writer): Debian's OpenMPI build, the one Trilinos'
# EpetraExt already loads into the process (the serial build beside it would define the same
# symbols twice); used through its serial C API. Debian: libhdf5-openmpi-dev.
find_path(HDF5_INCLUDE_DIR hdf5.h PATH_SUFFIXES hdf5/openmpi ${_contactlab_required})
find_library(HDF5_LIBRARY hdf5_openmpi ${_contactlab_required})
find_path(MUMPS_INCLUDE_DIR dmumps_c.h HINTS ${_contactlab_hint_MUMPS} ${_contactlab_required})
# Debian's libmumps-dev orders with PORD only; libmumps-ptscotch-dev (the same MUMPS built with
# SCOTCH and PT-SCOTCH) is preferred when present: SCOTCH's nested dissection cuts the
# factorization's flops on 3D meshes (doc/performance.md). Both its libraries must come before
# the PORD-only ones that Trilinos' Amesos pulls in, so that every MUMPS symbol resolves to one
# build: linking them directly from contactlab_linear puts them first.
find_library(MUMPS_LIBRARY NAMES dmumps_ptscotch dmumps HINTS ${_contactlab_hint_MUMPS}
             ${_contactlab_required})
# The single-precision MUMPS of the same build factorizes large matrices whose solves are then
# refined in double (Linear Solver/mumps/Precision, doc/performance.md).
if(MUMPS_LIBRARY MATCHES "ptscotch")
  find_library(MUMPS_SINGLE_LIBRARY smumps_ptscotch HINTS ${_contactlab_hint_MUMPS}
               ${_contactlab_required})
  find_library(MUMPS_COMMON_LIBRARY mumps_common_ptscotch HINTS ${_contactlab_hint_MUMPS}
               ${_contactlab_required})
else()
  find_library(MUMPS_SINGLE_LIBRARY smumps HINTS ${_contactlab_hint_MUMPS}
               ${_contactlab_required})
  find_library(MUMPS_COMMON_LIBRARY mumps_common HINTS ${_contactlab_hint_MUMPS}
               ${_contactlab_required})
endif()

if(_contactlab_in_config)
  foreach(_contactlab_var GMSH_INCLUDE_DIR GMSH_LIBRARY METIS_INCLUDE_DIR METIS_LIBRARY
                          MUMPS_INCLUDE_DIR MUMPS_LIBRARY MUMPS_SINGLE_LIBRARY
                          MUMPS_COMMON_LIBRARY)
    if(NOT ${_contactlab_var})
      string(CONCAT contactlab_NOT_FOUND_MESSAGE
        "contactlab needs ${_contactlab_var} (Debian: libgmsh-dev, libmetis-dev, libmumps-dev): "
        "set ${_contactlab_var} or add its prefix to CMAKE_PREFIX_PATH.")
      set(contactlab_FOUND FALSE)
      return()
    endif()
  endforeach()
endif()

# Our MUMPS libraries as one link item that records them even where nothing references them
# (as-needed off around them), for a library whose link line also brings in Trilinos' targets,
# which carry Debian's PORD-only MUMPS (algorithms/CMakeLists.txt).
set(CONTACTLAB_MUMPS_FIRST
    "-Wl,--no-as-needed,${MUMPS_LIBRARY},${MUMPS_SINGLE_LIBRARY},${MUMPS_COMMON_LIBRARY},--as-needed")

foreach(lib GMSH METIS MUMPS)
  if(NOT TARGET contactlab::${lib})
    add_library(contactlab::${lib} INTERFACE IMPORTED)
    set(_libs ${${lib}_LIBRARY})
    if(lib STREQUAL "MUMPS")
      list(APPEND _libs ${MUMPS_SINGLE_LIBRARY} ${MUMPS_COMMON_LIBRARY})
    endif()
    set_target_properties(contactlab::${lib} PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${${lib}_INCLUDE_DIR}"
      INTERFACE_LINK_LIBRARIES "${_libs}")
    if(lib STREQUAL "MUMPS" AND MUMPS_LIBRARY MATCHES "ptscotch")
      set_property(TARGET contactlab::MUMPS PROPERTY INTERFACE_COMPILE_DEFINITIONS
                   CONTACTLAB_MUMPS_HAS_SCOTCH=1)
    endif()
  endif()
endforeach()
