# `cmake --install`: the bpmkit program, the libraries (bpmkit::core, ::io, ::verify, ::structure,
# ::dsm, ::ste, ::calibrate), their headers under include/bpmkit/ (the src/ tree, so the libraries'
# own includes resolve), and a package a program finds with find_package(bpmkit)
# (tests/install_consumer is such a program; scripts/test.sh builds it against an install).
include(CMakePackageConfigHelpers)

set(BPMKIT_LIBRARIES bpmkit_core bpmkit_solvers bpmkit_statics bpmkit_io bpmkit_verify bpmkit_structure bpmkit_dsm bpmkit_ste
                     bpmkit_calibrate)
foreach(library IN LISTS BPMKIT_LIBRARIES)
  string(REPLACE "bpmkit_" "" name ${library})
  set_target_properties(${library} PROPERTIES EXPORT_NAME ${name})
endforeach()

# The public headers hold fixed-size Eigen matrices (6x6, 12x12), whose alignment follows the
# vector instructions enabled: a program must be compiled for the same ones as the libraries.
if(BPMKIT_NATIVE AND BPMKIT_HAS_MARCH_NATIVE)
  target_compile_options(bpmkit_core INTERFACE $<INSTALL_INTERFACE:-march=native>)
endif()

install(TARGETS ${BPMKIT_LIBRARIES} EXPORT bpmkitTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS bpmkit RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/bpmkit
        FILES_MATCHING PATTERN "*.hpp" PATTERN "cli" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/scripts/bpmkit_plot.py DESTINATION ${CMAKE_INSTALL_DATADIR}/bpmkit)

set(BPMKIT_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/bpmkit)
install(EXPORT bpmkitTargets NAMESPACE bpmkit:: DESTINATION ${BPMKIT_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/bpmkitConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/bpmkitConfig.cmake INSTALL_DESTINATION ${BPMKIT_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/bpmkitConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/bpmkitConfig.cmake ${PROJECT_BINARY_DIR}/bpmkitConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/bpmkitImportedLibraries.cmake
        DESTINATION ${BPMKIT_CMAKE_DIR})
