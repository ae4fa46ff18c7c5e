# Fails unless LIBRARY exports exactly the functions HEADER declares. The statically linked core
# and YAML code, and the C++ templates they instantiate, must stay private to libbrdfnav.so.
# Usage: cmake -DNM=nm -DLIBRARY=libbrdfnav.so -DHEADER=brdfnav.h -P check_exports.cmake
execute_process(COMMAND ${NM} -D --defined-only ${LIBRARY}
  OUTPUT_VARIABLE nm_output RESULT_VARIABLE nm_result)
if(NOT nm_result EQUAL 0)
  message(FATAL_ERROR "${NM} -D ${LIBRARY} failed (${nm_result})")
endif()
string(REGEX MATCHALL "[^\n]+" lines "${nm_output}")
set(exported)
foreach(line IN LISTS lines)
  # "0000000000001234 T name": the symbol is the last field.
  string(REGEX REPLACE "^.* " "" symbol "${line}")
  list(APPEND exported ${symbol})
endforeach()

file(READ ${HEADER} header)
# Declarations only ("BRDFNAV_API type name("), not the functions the comments mention.
string(REGEX MATCHALL "BRDFNAV_API[^(;]*[ *]brdfnav_[a-z_]+\\(" calls "${header}")
set(declared)
foreach(call IN LISTS calls)
  string(REGEX REPLACE "^.*[ *](brdfnav_[a-z_]+)\\($" "\\1" name "${call}")
  list(APPEND declared ${name})
endforeach()

list(REMOVE_DUPLICATES exported)
list(REMOVE_DUPLICATES declared)
list(SORT exported)
list(SORT declared)
if(NOT exported STREQUAL declared)
  set(extra ${exported})
  list(REMOVE_ITEM extra ${declared})
  set(missing ${declared})
  list(REMOVE_ITEM missing ${exported})
  message(FATAL_ERROR "exports of ${LIBRARY} differ from ${HEADER}\n"
                      "  exported, not declared: ${extra}\n  declared, not exported: ${missing}")
endif()
list(LENGTH exported count)
message(STATUS "${count} symbols exported, all declared in ${HEADER}")
