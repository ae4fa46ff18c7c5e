# The host's path: `cmake --install` the build tree into a fresh prefix, then configure, build and
# run tests/consumer, which finds the package with find_package(brdfnav) and links brdfnav::plugin.
# Usage: cmake -DBUILD_DIR=... -DCONSUMER_DIR=... -DWORK_DIR=... -DGENERATOR=... [-DCONFIG=...]
#        -P install_consumer.cmake
foreach(var BUILD_DIR CONSUMER_DIR WORK_DIR GENERATOR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "install_consumer.cmake: -D${var}=... is required")
  endif()
endforeach()

# A directory per run, so that parallel or repeated runs never share files.
string(RANDOM LENGTH 12 run_id)
set(work ${WORK_DIR}/${run_id})
set(prefix ${work}/prefix)
file(REMOVE_RECURSE ${work})

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output
                  ERROR_VARIABLE output)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "failed (${result}): ${ARGN}\n${output}")
  endif()
  set(run_output "${output}" PARENT_SCOPE)
endfunction()

set(config_args)
if(CONFIG)
  set(config_args --config ${CONFIG})
endif()
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} --component plugin ${config_args})

# Hosts get the C header only; the project's C++ headers stay out of the package.
file(GLOB_RECURSE headers RELATIVE ${prefix}/include ${prefix}/include/*)
if(NOT headers STREQUAL "brdfnav/brdfnav.h")
  message(FATAL_ERROR "installed headers: '${headers}', expected only brdfnav/brdfnav.h")
endif()

run(${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${work}/build -G ${GENERATOR}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
# The package must come from the fresh prefix, not from anything else on the machine.
file(STRINGS ${work}/build/CMakeCache.txt package_dir REGEX "^brdfnav_DIR:")
if(NOT package_dir MATCHES "^brdfnav_DIR:PATH=${prefix}/")
  message(FATAL_ERROR "find_package(brdfnav) used '${package_dir}', not ${prefix}")
endif()
run(${CMAKE_COMMAND} --build ${work}/build)
run(${work}/build/consumer)
message(STATUS "consumer: ${run_output}")
file(REMOVE_RECURSE ${work})
