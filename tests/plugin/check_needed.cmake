# Fails unless every shared library LIBRARY names as NEEDED (readelf -d) matches the regular
# expression ALLOWED (anchored at both ends). What a library needs is what a host's process
# takes in with it.
# Usage: cmake -DREADELF=readelf -DLIBRARY=lib.so -DALLOWED="libc\\.so\\.6|..." -P check_needed.cmake
foreach(var READELF LIBRARY ALLOWED)
  if(NOT ${var})
    message(FATAL_ERROR "check_needed.cmake: -D${var}=... is required")
  endif()
endforeach()
execute_process(COMMAND ${READELF} -d ${LIBRARY} OUTPUT_VARIABLE dynamic RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${READELF} -d ${LIBRARY} failed (${result})")
endif()
# " 0x0000000000000001 (NEEDED)             Shared library: [libc.so.6]"
string(REGEX MATCHALL "\\(NEEDED\\)[^\n]*\\[[^]]+\\]" lines "${dynamic}")
set(needed)
set(unexpected)
foreach(line IN LISTS lines)
  string(REGEX REPLACE "^.*\\[([^]]+)\\]$" "\\1" name "${line}")
  list(APPEND needed ${name})
  if(NOT name MATCHES "^(${ALLOWED})$")
    list(APPEND unexpected ${name})
  endif()
endforeach()
if(NOT needed)
  message(FATAL_ERROR "${LIBRARY}: no NEEDED entry found in readelf's output:\n${dynamic}")
endif()
if(unexpected)
  message(FATAL_ERROR "${LIBRARY} needs libraries beyond those allowed (${ALLOWED}): "
                      "${unexpected}\n  all it needs: ${needed}")
endif()
message(STATUS "${LIBRARY} needs: ${needed}")
