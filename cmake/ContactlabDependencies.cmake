# Third-party dependencies, all from Debian 12 packages (cmake/debian-packages.txt).
# Each becomes an imported target so modules link only what they use.
find_package(MPI REQUIRED COMPONENTS C CXX)
find_package(Tpetra REQUIRED)
find_package(Amesos2 REQUIRED)
find_package(Belos REQUIRED)
find_package(Ifpack2 REQUIRED)
find_package(MueLu REQUIRED)
find_package(VTK 9 REQUIRED COMPONENTS CommonCore CommonDataModel IOXML)

foreach(pkg Tpetra Amesos2 Belos Ifpack2 MueLu)
  if(NOT TARGET contactlab::${pkg})
    add_library(contactlab::${pkg} INTERFACE IMPORTED)
    set_target_properties(contactlab::${pkg} PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${${pkg}_INCLUDE_DIRS};${${pkg}_TPL_INCLUDE_DIRS}"
      INTERFACE_LINK_LIBRARIES "${${pkg}_LIBRARIES};${${pkg}_TPL_LIBRARIES}"
      INTERFACE_LINK_DIRECTORIES "${${pkg}_LIBRARY_DIRS}")
  endif()
endforeach()

find_path(GMSH_INCLUDE_DIR gmsh.h REQUIRED)
find_library(GMSH_LIBRARY gmsh REQUIRED)
find_path(METIS_INCLUDE_DIR metis.h REQUIRED)
find_library(METIS_LIBRARY metis REQUIRED)
find_path(MUMPS_INCLUDE_DIR dmumps_c.h REQUIRED)
find_library(MUMPS_LIBRARY dmumps REQUIRED)
find_library(MUMPS_COMMON_LIBRARY mumps_common REQUIRED)

foreach(lib GMSH METIS MUMPS)
  if(NOT TARGET contactlab::${lib})
    add_library(contactlab::${lib} INTERFACE IMPORTED)
    set(_libs ${${lib}_LIBRARY})
    if(lib STREQUAL "MUMPS")
      list(APPEND _libs ${MUMPS_COMMON_LIBRARY})
    endif()
    set_target_properties(contactlab::${lib} PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${${lib}_INCLUDE_DIR}"
      INTERFACE_LINK_LIBRARIES "${_libs}")
  endif()
endforeach()
