# cmake -DCLI=brdfnav -DOUT=DIR -DPROFILE=test -P build_test_database.cmake: the CTest fixture
# test_database (tests/CMakeLists.txt), built afresh in every run so that no suite reads one an
# older build wrote.
file(REMOVE_RECURSE ${OUT} ${OUT}.partial)
execute_process(COMMAND ${CLI} precompute --profile ${PROFILE} --out ${OUT}
                RESULT_VARIABLE status ERROR_VARIABLE log)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${CLI} precompute --profile ${PROFILE} --out ${OUT}: exit ${status}\n${log}")
endif()
