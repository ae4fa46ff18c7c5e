# Sanitized builds, for `./run check` and `./run fuzz` (docs/RELIABILITY.md).
#   BRDFNAV_SANITIZE=address,undefined or thread: every target is built and linked with it.
#   BRDFNAV_FUZZ=ON (clang): ASan + UBSan, libFuzzer's coverage instrumentation in every target, so
#   the fuzzers of tests/fuzz see the branches of the code they feed, and those fuzzers beside the
#   test suite: one tree serves `./run check` and `./run fuzz`.
set(BRDFNAV_SANITIZE "" CACHE STRING "Sanitizers for every target (-fsanitize=...), e.g. address,undefined")
option(BRDFNAV_FUZZ "Build the libFuzzer targets too, with ASan + UBSan (clang)" OFF)

if(BRDFNAV_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "BRDFNAV_FUZZ needs clang (-DCMAKE_CXX_COMPILER=clang++)")
  endif()
  set(BRDFNAV_SANITIZE "address,undefined")
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

if(BRDFNAV_SANITIZE)
  add_compile_options(-fsanitize=${BRDFNAV_SANITIZE} -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${BRDFNAV_SANITIZE})
  if(BRDFNAV_SANITIZE MATCHES "undefined")
    # A report is a failure (a test or a fuzz input fails), not a line in a log.
    add_compile_options(-fno-sanitize-recover=undefined)
  endif()
endif()
