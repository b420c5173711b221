# Writes build/include/beamimpact/version.hpp with the project version and git description,
# so every output can say which code produced it. The description is taken again at every build
# (target beamimpact_version, run before beamimpact_core compiles), not only at configure time: a
# commit or an edit after configuring must not leave outputs labelled with an older version.
# The file is rewritten only when the description changed, so an unchanged tree rebuilds nothing.
# Script mode: cmake -DSOURCE_DIR=... -DOUT=... -DPROJECT_VERSION=... -P cmake/version.cmake
if(CMAKE_SCRIPT_MODE_FILE)
  find_package(Git QUIET)
  set(BEAMIMPACT_GIT "unknown")
  if(GIT_FOUND)
    execute_process(COMMAND ${GIT_EXECUTABLE} describe --always --dirty --tags
      WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE BEAMIMPACT_GIT
      OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(NOT BEAMIMPACT_GIT)
      set(BEAMIMPACT_GIT "unknown")
    endif()
  endif()
  configure_file(${SOURCE_DIR}/cmake/version.hpp.in ${OUT} @ONLY)
  return()
endif()

set(_version_args -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DPROJECT_VERSION=${PROJECT_VERSION}
  -DOUT=${BEAMIMPACT_INCLUDE_DIR}/beamimpact/version.hpp -P ${PROJECT_SOURCE_DIR}/cmake/version.cmake)
execute_process(COMMAND ${CMAKE_COMMAND} ${_version_args})  # the header exists from configure on
add_custom_target(beamimpact_version ALL COMMAND ${CMAKE_COMMAND} ${_version_args}
  BYPRODUCTS ${BEAMIMPACT_INCLUDE_DIR}/beamimpact/version.hpp
  COMMENT "beamimpact version (git describe)" VERBATIM)
