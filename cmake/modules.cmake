# Project-rooted includes: every module of cmake/modules.txt is reachable as
# <beamimpact/MODULE/file.hpp>. The build tree gets include/beamimpact/MODULE -> its folder
# (a symbolic link, so edits need no copy); the install tree gets a copy of its public headers.
set(BEAMIMPACT_INCLUDE_DIR ${PROJECT_BINARY_DIR}/include)
file(MAKE_DIRECTORY ${BEAMIMPACT_INCLUDE_DIR}/beamimpact)
file(STRINGS ${PROJECT_SOURCE_DIR}/cmake/modules.txt _beamimpact_module_lines REGEX "^[a-z*]")
set(BEAMIMPACT_MODULES "")
function(_beamimpact_module module folder)
  set(BEAMIMPACT_MODULES ${BEAMIMPACT_MODULES} ${module} PARENT_SCOPE)
  set(BEAMIMPACT_MODULE_DIR_${module} ${folder} PARENT_SCOPE)
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${folder} ${BEAMIMPACT_INCLUDE_DIR}/beamimpact/${module} SYMBOLIC)
endfunction()
foreach(_line IN LISTS _beamimpact_module_lines)
  string(REGEX MATCHALL "[^ \t]+" _fields "${_line}")
  list(GET _fields 0 _module)
  list(GET _fields 1 _folder)
  if(_module STREQUAL "*")  # every subfolder with C++ headers, named after it
    string(REPLACE "/*" "" _parent ${_folder})
    file(GLOB _subs LIST_DIRECTORIES true RELATIVE ${PROJECT_SOURCE_DIR}/${_parent} ${PROJECT_SOURCE_DIR}/${_parent}/*)
    list(SORT _subs)
    foreach(_sub IN LISTS _subs)
      file(GLOB _headers ${PROJECT_SOURCE_DIR}/${_parent}/${_sub}/*.hpp)
      if(_headers)
        _beamimpact_module(${_sub} ${_parent}/${_sub})
      endif()
    endforeach()
  else()
    _beamimpact_module(${_module} ${_folder})
  endif()
endforeach()

add_library(beamimpact_headers INTERFACE)
target_include_directories(beamimpact_headers INTERFACE $<BUILD_INTERFACE:${BEAMIMPACT_INCLUDE_DIR}>
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
