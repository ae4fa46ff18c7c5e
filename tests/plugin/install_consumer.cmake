# The host's path: `cmake --install` the build tree into a fresh prefix, then configure, build and
# run, against that prefix only,
# - tests/consumer: `consumer` (brdfnav::plugin) and `consumer_navigator` (brdfnav::navigator, on
#   the test database DATABASE);
# - examples/host: the example host, on a material that `brdfnav export` (CLI) wrote.
# A renderer's host takes at most 12 shared libraries into its process (ldd).
# Usage: cmake -DBUILD_DIR=... -DCONSUMER_DIR=... -DEXAMPLE_DIR=... -DWORK_DIR=... -DGENERATOR=...
#        -DCLI=... -DDATABASE=... [-DCONFIG=...] -P install_consumer.cmake
foreach(var BUILD_DIR CONSUMER_DIR EXAMPLE_DIR WORK_DIR GENERATOR CLI DATABASE)
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
foreach(component plugin navigator)
  run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} --component ${component}
      ${config_args})
endforeach()

# Hosts get the C headers only; the project's C++ headers stay out of the package.
file(GLOB_RECURSE headers RELATIVE ${prefix}/include ${prefix}/include/*)
list(SORT headers)
if(NOT headers STREQUAL "brdfnav/brdfnav.h;brdfnav/brdfnav_navigator.h")
  message(FATAL_ERROR "installed headers: '${headers}', expected brdfnav/brdfnav.h and "
                      "brdfnav/brdfnav_navigator.h")
endif()

# Configures and builds SOURCE into ${work}/NAME against the fresh prefix only.
function(build_against_prefix name source)
  run(${CMAKE_COMMAND} -S ${source} -B ${work}/${name} -G ${GENERATOR}
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix}
      -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
  # The package must come from the fresh prefix, not from anything else on the machine.
  file(STRINGS ${work}/${name}/CMakeCache.txt package_dir REGEX "^brdfnav_DIR:")
  if(NOT package_dir MATCHES "^brdfnav_DIR:PATH=${prefix}/")
    message(FATAL_ERROR "find_package(brdfnav) used '${package_dir}', not ${prefix}")
  endif()
  run(${CMAKE_COMMAND} --build ${work}/${name})
endfunction()

build_against_prefix(consumer ${CONSUMER_DIR})
run(${work}/consumer/consumer)
message(STATUS "consumer: ${run_output}")
run(${work}/consumer/consumer_navigator ${DATABASE})
message(STATUS "consumer_navigator: ${run_output}")

run(ldd ${work}/consumer/consumer)
string(REGEX MATCHALL "[^\n]+" libraries "${run_output}")
list(LENGTH libraries library_count)
if(library_count GREATER 12)
  message(FATAL_ERROR "a host of brdfnav::plugin loads ${library_count} shared libraries "
                      "(at most 12):\n${run_output}")
endif()
message(STATUS "consumer loads ${library_count} shared libraries")

build_against_prefix(example ${EXAMPLE_DIR})
run(${CLI} export --db ${DATABASE} --material he:sigma=0.5,tau=8,eta=1.6,rho_d=0.2,rho_s=0.6
    --out ${work}/exported.yaml)
run(${work}/example/brdfnav_example_host ${work}/exported.yaml 4000)
message(STATUS "example host:\n${run_output}")
file(REMOVE_RECURSE ${work})
