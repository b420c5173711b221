# cmake --install: the libraries, the public headers under include/beamimpact/ at their repository paths
# (included as <beamimpact/api/run.hpp>), the `beamimpact` program, the shipped scenes and matrix, the
# FEniCSx script, the page generator, and a CMake package
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
# The public headers: what a program using find_package(beamimpact) includes (running a scene,
# the method registry and methods files, loading a scene, exporting its model) and every project
# header they include, found by following their #include lines. Nothing else is installed: the
# methods' internals, kernels and test helpers stay in the source tree. tools/test-install.sh
# checks that each installed header's project includes are installed too.
set(BEAMIMPACT_PUBLIC_HEADERS api/run.hpp api/registry.hpp api/methods_file.hpp api/model_export.hpp
  solver/scene/scene_io.hpp)
set(_public "")
set(_todo ${BEAMIMPACT_PUBLIC_HEADERS})
while(_todo)
  list(POP_FRONT _todo _header)
  if(_header IN_LIST _public)
    continue()
  endif()
  list(APPEND _public ${_header})
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${_header})
  file(STRINGS ${PROJECT_SOURCE_DIR}/${_header} _includes REGEX "^#include <[^>]+>")
  foreach(_include IN LISTS _includes)
    string(REGEX REPLACE "^#include <([^>]+)>.*" "\\1" _include "${_include}")
    if(EXISTS ${PROJECT_SOURCE_DIR}/${_include} AND NOT IS_DIRECTORY ${PROJECT_SOURCE_DIR}/${_include})
      list(APPEND _todo ${_include})
    endif()
  endforeach()
endwhile()
# Installed, each header's project includes read <beamimpact/FOLDER/...>: the one spelling a
# consumer writes (include/ is the package's only include directory).
foreach(_header IN LISTS _public)
  get_filename_component(_dir ${_header} DIRECTORY)
  file(READ ${PROJECT_SOURCE_DIR}/${_header} _text)
  string(REGEX REPLACE "#include <((api|solver|references|verification)/[^>]+)>" "#include <beamimpact/\\1>"
    _text "${_text}")
  file(WRITE ${PROJECT_BINARY_DIR}/installed-headers/${_header} "${_text}")
  install(FILES ${PROJECT_BINARY_DIR}/installed-headers/${_header}
    DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/beamimpact/${_dir})
endforeach()
install(FILES ${BEAMIMPACT_INCLUDE_DIR}/beamimpact/version.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/beamimpact)
# Data: scenes, matrix and methods file (share/beamimpact/verification), the FEniCSx reference script.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/verification/scenes DESTINATION ${CMAKE_INSTALL_DATADIR}/beamimpact/verification)
install(FILES ${PROJECT_SOURCE_DIR}/verification/matrix.toml ${PROJECT_SOURCE_DIR}/verification/methods.toml
  ${PROJECT_SOURCE_DIR}/verification/cards.toml DESTINATION ${CMAKE_INSTALL_DATADIR}/beamimpact/verification)
# The Python references the methods file runs (every references/NAME with a run.py: FEniCSx, Siconos,
# GetFEM, ...), as setup.py's data_files lays them out.
file(GLOB _python_references LIST_DIRECTORIES false ${PROJECT_SOURCE_DIR}/references/*/run.py)
foreach(_run IN LISTS _python_references)
  get_filename_component(_folder ${_run} DIRECTORY)
  install(DIRECTORY ${_folder} DESTINATION ${CMAKE_INSTALL_DATADIR}/beamimpact/references
    FILES_MATCHING PATTERN "*.py" PATTERN "tests" EXCLUDE PATTERN "__pycache__" EXCLUDE)
endforeach()
# What they share (the contact-interval rule), beside them.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/references/common DESTINATION ${CMAKE_INSTALL_DATADIR}/beamimpact/references
  FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/examples/external_solver/penalty_central.py
  DESTINATION ${CMAKE_INSTALL_DATADIR}/beamimpact/examples/external_solver)
# The page generator (reports/page_files.txt, as setup.py ships it): score and conform make their
# HTML pages with it from the installed tree.
file(STRINGS ${PROJECT_SOURCE_DIR}/reports/page_files.txt _page_files REGEX "^[^#]")
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/reports/page_files.txt)
list(TRANSFORM _page_files PREPEND ${PROJECT_SOURCE_DIR}/reports/)
install(FILES ${_page_files} DESTINATION ${CMAKE_INSTALL_DATADIR}/beamimpact/reports)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/reports/templates DESTINATION ${CMAKE_INSTALL_DATADIR}/beamimpact/reports
  FILES_MATCHING PATTERN "*.j2")

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
