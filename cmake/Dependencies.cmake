# Third-party libraries from Debian's packages (scripts/install-deps.sh installs them) besides those
# the top-level CMakeLists.txt finds: MPI and SUNDIALS, and the imported targets of
# cmake/bpmkitImportedLibraries.cmake, so the library targets link to names, not paths.
#   SUNDIALS::kinsol_shared, SUNDIALS::nvecserial_shared  KINSOL Newton-Krylov (libsundials-dev)
find_package(MPI REQUIRED COMPONENTS CXX)
find_package(SUNDIALS 6 REQUIRED CONFIG)
include(bpmkitImportedLibraries)
