# Fails when LIBRARY holds the database builder (its renderer, PCA, fits, precompute job), or
# loads, directly or through the libraries it needs (ldd: the whole list the loader maps into a
# host's process), a library of the builder or of the image stack: OpenBLAS, BLAS, LAPACK,
# OpenImageIO, OpenCV, Embree, tinyobjloader. It reads the database's images with OpenEXR alone.
# The number of libraries it loads is printed, and must stay within MAX_LOADED.
# Usage: cmake -DNM=nm -DREADELF=readelf -DLDD=ldd -DMAX_LOADED=N -DLIBRARY=lib.so
#        -P check_no_builder.cmake
foreach(var NM READELF LDD MAX_LOADED LIBRARY)
  if(NOT ${var})
    message(FATAL_ERROR "check_no_builder.cmake: -D${var}=... is required")
  endif()
endforeach()
execute_process(COMMAND ${READELF} -d ${LIBRARY} OUTPUT_VARIABLE dynamic RESULT_VARIABLE r1)
execute_process(COMMAND ${NM} -C ${LIBRARY} OUTPUT_VARIABLE symbols RESULT_VARIABLE r2)
execute_process(COMMAND ${LDD} ${LIBRARY} OUTPUT_VARIABLE loaded RESULT_VARIABLE r3
                ERROR_VARIABLE ldd_error)
if(NOT r1 EQUAL 0 OR NOT r2 EQUAL 0 OR NOT r3 EQUAL 0)
  message(FATAL_ERROR "readelf, nm or ldd failed on ${LIBRARY} (${r1}, ${r2}, ${r3}) ${ldd_error}")
endif()
if(loaded MATCHES "not found")
  message(FATAL_ERROR "${LIBRARY}: ldd cannot resolve every library:\n${loaded}")
endif()
string(REGEX MATCHALL "Shared library: \\[(libopenblas|libembree|libtinyobjloader)[^]]*\\]"
       builder_libraries "${dynamic}")
if(builder_libraries)
  message(FATAL_ERROR "${LIBRARY} needs the builder's libraries: ${builder_libraries}")
endif()
# "\tlibfoo.so.1 => /usr/lib/x86_64-linux-gnu/libfoo.so.1 (0x...)", "\tlinux-vdso.so.1 (0x...)"
string(REGEX MATCHALL "[^\n\t ]+ (=> [^\n]+ )?\\(0x[0-9a-f]+\\)" lines "${loaded}")
list(LENGTH lines count)
set(forbidden)
foreach(line IN LISTS lines)
  string(REGEX REPLACE " .*$" "" name "${line}")
  string(TOLOWER "${name}" lower)
  if(lower MATCHES "blas|lapack|openimageio|opencv|embree|tinyobjloader")
    list(APPEND forbidden ${name})
  endif()
endforeach()
if(forbidden)
  message(FATAL_ERROR "${LIBRARY} loads (ldd, transitively) ${forbidden}; of its ${count} "
                      "libraries none may be OpenBLAS, BLAS, LAPACK, OpenImageIO, OpenCV, Embree "
                      "or tinyobjloader:\n${loaded}")
endif()
if(count GREATER MAX_LOADED)
  message(FATAL_ERROR "${LIBRARY} loads ${count} libraries (ldd), more than ${MAX_LOADED}: what "
                      "does it bring into a host now?\n${loaded}")
endif()
string(REGEX MATCHALL
       "brdfnav::(Renderer|uncentered_pca|fit_lobe|precompute_database|merge_shards|EnvMap|write_exr)[^\n]*"
       builder_symbols "${symbols}")
if(builder_symbols)
  list(LENGTH builder_symbols symbol_count)
  list(GET builder_symbols 0 first)
  message(FATAL_ERROR "${LIBRARY} holds ${symbol_count} symbols of the builder, first: ${first}")
endif()
message(STATUS "${LIBRARY}: no builder symbol, no builder or image-stack library; "
               "loads ${count} libraries (ldd)")
