# Third-party libraries from Debian's packages (scripts/install-deps.sh installs them) besides those
# the top-level CMakeLists.txt finds: MPI, and the imported targets of
# cmake/bpmkitImportedLibraries.cmake, so the library targets link to names, not paths.
find_package(MPI REQUIRED COMPONENTS CXX)
include(bpmkitImportedLibraries)
