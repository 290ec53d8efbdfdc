# Third-party libraries from Debian's packages (scripts/install-deps.sh installs them). Packages
# without a CMake config file (SuiteSparse 5, hypre, voro++) get imported targets here, so the
# library targets link to names, not paths:
#   bpmkit::cholmod  SuiteSparse CHOLMOD, sparse Cholesky (libsuitesparse-dev)
#   bpmkit::hypre    hypre BoomerAMG + PCG; Debian builds it with MPI (libhypre-dev, libopenmpi-dev)
#   bpmkit::voro     voro++ Voronoi cells (voro++-dev)
#   SUNDIALS::kinsol_shared, SUNDIALS::nvecserial_shared  KINSOL Newton-Krylov (libsundials-dev)
find_package(MPI REQUIRED COMPONENTS CXX)
find_package(SUNDIALS 6 REQUIRED CONFIG)

function(bpmkit_import_library target header library)
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
