# Imported targets for the Debian packages without a CMake config file, by their header and library
# names. Included by cmake/Dependencies.cmake when bpmkit is built, and by the installed
# bpmkitConfig.cmake (cmake/Install.cmake), since a program linking the static bpmkit libraries
# links these too:
#   bpmkit::cholmod  SuiteSparse CHOLMOD, sparse Cholesky (libsuitesparse-dev)
#   bpmkit::hypre    hypre BoomerAMG + PCG; Debian builds it with MPI (libhypre-dev, libopenmpi-dev)
#   bpmkit::voro     voro++ Voronoi cells (voro++-dev)
# MPI::MPI_CXX must exist first (find_package(MPI COMPONENTS CXX)).
function(bpmkit_import_library target header library)
  if(TARGET ${target})
    return()
  endif()
  string(REPLACE "::" "_" var ${target})
  find_path(${var}_INCLUDE ${header} PATH_SUFFIXES suitesparse hypre voro++ REQUIRED)
  find_library(${var}_LIBRARY ${library} REQUIRED)
  add_library(${target} UNKNOWN IMPORTED)
  set_target_properties(${target} PROPERTIES IMPORTED_LOCATION ${${var}_LIBRARY}
                                             INTERFACE_INCLUDE_DIRECTORIES ${${var}_INCLUDE})
endfunction()

bpmkit_import_library(bpmkit::cholmod cholmod.h cholmod)
bpmkit_import_library(bpmkit::hypre HYPRE.h HYPRE)
set_property(TARGET bpmkit::hypre APPEND PROPERTY INTERFACE_LINK_LIBRARIES MPI::MPI_CXX)
bpmkit_import_library(bpmkit::voro voro++.hh voro++)
