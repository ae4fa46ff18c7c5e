# Fails unless every C and C++ source of the project is formatted by the checked-in .clang-format,
# naming the files that are not (the fix: clang-format -i FILE). Sources are globbed when the test
# runs, so a file added since CMake ran is checked too.
# Usage: cmake -DCLANG_FORMAT=clang-format-14 -DROOT=source-dir -P check_format.cmake
set(sources)
foreach(dir app bench core navigator ocio plugin precompute studies tests)
  file(GLOB_RECURSE found ${ROOT}/${dir}/*.cpp ${ROOT}/${dir}/*.h ${ROOT}/${dir}/*.c)
  list(APPEND sources ${found})
endforeach()
list(FILTER sources EXCLUDE REGEX "/node_modules/")
set(unformatted)
foreach(source IN LISTS sources)
  execute_process(COMMAND ${CLANG_FORMAT} --dry-run -Werror --style=file ${source}
    WORKING_DIRECTORY ${ROOT} RESULT_VARIABLE result OUTPUT_QUIET ERROR_QUIET)
  if(NOT result EQUAL 0)
    file(RELATIVE_PATH relative ${ROOT} ${source})
    list(APPEND unformatted ${relative})
  endif()
endforeach()
list(LENGTH sources count)
if(unformatted)
  list(JOIN unformatted "\n  " listed)
  message(FATAL_ERROR "not formatted by .clang-format (run clang-format -i on them):\n  ${listed}")
endif()
message(STATUS "${count} sources formatted by .clang-format")
