# Project-rooted includes: a header is included by its path from the repository root
# (<solver/model/Model.hpp>), in the build tree and, under include/beamimpact/, in the installed
# package. cmake/modules.txt lists the modules (folder, library, namespace); the generated
# <beamimpact/version.hpp> lives in the build tree's include/.
set(BEAMIMPACT_INCLUDE_DIR ${PROJECT_BINARY_DIR}/include)
file(MAKE_DIRECTORY ${BEAMIMPACT_INCLUDE_DIR}/beamimpact)
file(STRINGS ${PROJECT_SOURCE_DIR}/cmake/modules.txt _beamimpact_module_lines REGEX "^[a-z*]")
set(BEAMIMPACT_MODULE_DIRS "")
foreach(_line IN LISTS _beamimpact_module_lines)
  string(REGEX MATCHALL "[^ \t]+" _fields "${_line}")
  list(GET _fields 1 _folder)
  if(_folder MATCHES "/\\*$")  # every subfolder with C++ headers
    string(REPLACE "/*" "" _parent ${_folder})
    file(GLOB _subs LIST_DIRECTORIES true RELATIVE ${PROJECT_SOURCE_DIR}/${_parent} ${PROJECT_SOURCE_DIR}/${_parent}/*)
    list(SORT _subs)
    foreach(_sub IN LISTS _subs)
      file(GLOB _headers ${PROJECT_SOURCE_DIR}/${_parent}/${_sub}/*.hpp)
      if(_headers)
        list(APPEND BEAMIMPACT_MODULE_DIRS ${_parent}/${_sub})
      endif()
    endforeach()
  else()
    list(APPEND BEAMIMPACT_MODULE_DIRS ${_folder})
  endif()
endforeach()

add_library(beamimpact_headers INTERFACE)
target_include_directories(beamimpact_headers INTERFACE
  $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}> $<BUILD_INTERFACE:${BEAMIMPACT_INCLUDE_DIR}>
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
# beamimpact_library(NAME SOURCES ... [PUBLIC libs...] [PRIVATE libs...]): a library of the
# public API, exported as beamimpact::NAME (without the beamimpact_ prefix) and installed.
function(beamimpact_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  add_library(${name} ${ARG_SOURCES})
  string(REPLACE "beamimpact_" "" _export ${name})
  set_target_properties(${name} PROPERTIES EXPORT_NAME ${_export} POSITION_INDEPENDENT_CODE ON)
  target_link_libraries(${name} PUBLIC beamimpact_headers ${ARG_PUBLIC}
    PRIVATE ${ARG_PRIVATE} $<BUILD_INTERFACE:beamimpact_warnings>)
  set_property(GLOBAL APPEND PROPERTY BEAMIMPACT_LIBRARIES ${name})
endfunction()
