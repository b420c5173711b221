# Sanitizers and debug checks, for every target of the project.
# - Debug builds: -D_GLIBCXX_ASSERTIONS (bounds-checked operator[], front/back on empty, ...).
# - BEAMIMPACT_SANITIZE=ON: AddressSanitizer + UndefinedBehaviorSanitizer, any error aborts.
#   float-cast-overflow (a double too large for its integer type, e.g. a step count) is not part
#   of -fsanitize=undefined in GCC; it is added where the compiler knows it. tools/sanitize.sh
#   builds this with clang into build-asan/.
include(CheckCXXCompilerFlag)

option(BEAMIMPACT_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)

add_compile_definitions($<$<CONFIG:Debug>:_GLIBCXX_ASSERTIONS>)

if(BEAMIMPACT_SANITIZE)
  set(_san address,undefined)
  set(CMAKE_REQUIRED_LINK_OPTIONS -fsanitize=float-cast-overflow)
  check_cxx_compiler_flag(-fsanitize=float-cast-overflow BEAMIMPACT_HAS_FLOAT_CAST_OVERFLOW)
  unset(CMAKE_REQUIRED_LINK_OPTIONS)
  if(BEAMIMPACT_HAS_FLOAT_CAST_OVERFLOW)
    string(APPEND _san ",float-cast-overflow")
  endif()
  # Line tables only: file:line in the reports at a fraction of the compile time of full -g.
  check_cxx_compiler_flag(-gline-tables-only BEAMIMPACT_HAS_LINE_TABLES)
  add_compile_options(-fsanitize=${_san} -fno-sanitize-recover=all -fno-omit-frame-pointer
    $<IF:$<BOOL:${BEAMIMPACT_HAS_LINE_TABLES}>,-gline-tables-only,-g1>)
  add_link_options(-fsanitize=${_san})
  add_compile_definitions(_GLIBCXX_ASSERTIONS)
  message(STATUS "beamimpact: sanitizers ${_san}")
endif()
