# cmake --install: the libraries, the public headers under include/beamimpact/ at their repository paths, the
# `beamimpact` program, the shipped scenes and matrix, the FEniCSx script, and a CMake package
# so that another project writes find_package(beamimpact) and links beamimpact::beamimpact.
include(CMakePackageConfigHelpers)

get_property(_libraries GLOBAL PROPERTY BEAMIMPACT_LIBRARIES)
add_library(beamimpact_all INTERFACE)
set_target_properties(beamimpact_all PROPERTIES EXPORT_NAME beamimpact)
target_link_libraries(beamimpact_all INTERFACE ${_libraries})
add_library(beamimpact::beamimpact ALIAS beamimpact_all)

install(TARGETS beamimpact_headers ${_libraries} beamimpact_all EXPORT beamimpactTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS beamimpact RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
foreach(_dir IN LISTS BEAMIMPACT_MODULE_DIRS)
  if(NOT _dir STREQUAL "solver/testing")
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/${_dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/beamimpact/${_dir}
      FILES_MATCHING PATTERN "*.hpp" PATTERN "test_*" EXCLUDE PATTERN "tests" EXCLUDE)
  endif()
endforeach()
install(FILES ${BEAMIMPACT_INCLUDE_DIR}/beamimpact/version.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/beamimpact)
# Data: scenes, matrix and methods file (share/beamimpact/verification), the FEniCSx reference script.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/verification/scenes DESTINATION ${CMAKE_INSTALL_DATADIR}/beamimpact/verification)
install(FILES ${PROJECT_SOURCE_DIR}/verification/matrix.toml ${PROJECT_SOURCE_DIR}/verification/methods.toml
  DESTINATION ${CMAKE_INSTALL_DATADIR}/beamimpact/verification)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/references/fenicsx DESTINATION ${CMAKE_INSTALL_DATADIR}/beamimpact/references
  FILES_MATCHING PATTERN "*.py" PATTERN "tests" EXCLUDE PATTERN "__pycache__" EXCLUDE)
# The Siconos adapter and the minimal outside solver (Python, run on `beamimpact model`'s export).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/references/siconos DESTINATION ${CMAKE_INSTALL_DATADIR}/beamimpact/references
  FILES_MATCHING PATTERN "*.py" PATTERN "tests" EXCLUDE PATTERN "__pycache__" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/examples/external_solver/penalty_central.py
  DESTINATION ${CMAKE_INSTALL_DATADIR}/beamimpact/examples/external_solver)

set(_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/beamimpact)
install(EXPORT beamimpactTargets NAMESPACE beamimpact:: DESTINATION ${_cmake_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/beamimpactConfig.cmake.in
  ${PROJECT_BINARY_DIR}/beamimpactConfig.cmake INSTALL_DESTINATION ${_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/beamimpactConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/beamimpactConfig.cmake ${PROJECT_BINARY_DIR}/beamimpactConfigVersion.cmake
  DESTINATION ${_cmake_dir})

# The example consumer is built against an installed tree by the test command
# (tools/run-tests.sh: install into build/install, then configure examples/consumer).
