# Fails when LIBRARY holds the database builder (its renderer, PCA, fits, precompute job) or needs
# a library only the builder uses (OpenBLAS, Embree, tinyobjloader).
# Usage: cmake -DNM=nm -DREADELF=readelf -DLIBRARY=lib.so -P check_no_builder.cmake
execute_process(COMMAND ${READELF} -d ${LIBRARY} OUTPUT_VARIABLE dynamic RESULT_VARIABLE r1)
execute_process(COMMAND ${NM} -C ${LIBRARY} OUTPUT_VARIABLE symbols RESULT_VARIABLE r2)
if(NOT r1 EQUAL 0 OR NOT r2 EQUAL 0)
  message(FATAL_ERROR "readelf or nm failed on ${LIBRARY} (${r1}, ${r2})")
endif()
string(REGEX MATCHALL "Shared library: \\[(libopenblas|libembree|libtinyobjloader)[^]]*\\]"
       builder_libraries "${dynamic}")
if(builder_libraries)
  message(FATAL_ERROR "${LIBRARY} needs the builder's libraries: ${builder_libraries}")
endif()
string(REGEX MATCHALL
       "brdfnav::(Renderer|uncentered_pca|fit_lobe|precompute_database|merge_shards|EnvMap)[^\n]*"
       builder_symbols "${symbols}")
if(builder_symbols)
  list(LENGTH builder_symbols count)
  list(GET builder_symbols 0 first)
  message(FATAL_ERROR "${LIBRARY} holds ${count} symbols of the builder, first: ${first}")
endif()
message(STATUS "${LIBRARY}: no builder symbol, no builder library")
