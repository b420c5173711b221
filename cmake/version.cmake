# Writes build/include/beamimpact/version.hpp with the project version and git description,
# so every output can say which code produced it.
find_package(Git QUIET)
set(BEAMIMPACT_GIT "unknown")
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} describe --always --dirty --tags
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} OUTPUT_VARIABLE BEAMIMPACT_GIT
    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT BEAMIMPACT_GIT)
    set(BEAMIMPACT_GIT "unknown")
  endif()
endif()
configure_file(${PROJECT_SOURCE_DIR}/cmake/version.hpp.in
  ${BEAMIMPACT_INCLUDE_DIR}/beamimpact/version.hpp @ONLY)
