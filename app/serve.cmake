# `brdfnav serve`, the navigator's HTTP server (docs/SERVE.md): the JSON API over cpp-httplib and
# the page of app/web/, embedded into the executable. Included by app/CMakeLists.txt after
# brdfnav_cli is defined.
find_package(PkgConfig REQUIRED)
pkg_check_modules(brdfnav_httplib REQUIRED IMPORTED_TARGET cpp-httplib)
find_package(nlohmann_json 3 CONFIG REQUIRED)

set(brdfnav_web_files index.html app.js style.css favicon.svg)
list(TRANSFORM brdfnav_web_files PREPEND ${CMAKE_CURRENT_SOURCE_DIR}/web/ OUTPUT_VARIABLE web_deps)
list(JOIN brdfnav_web_files "|" web_list)
set(web_cpp ${CMAKE_CURRENT_BINARY_DIR}/web_assets.cpp)
add_custom_command(OUTPUT ${web_cpp}
  COMMAND ${CMAKE_COMMAND} -DOUT=${web_cpp} -DROOT=${CMAKE_CURRENT_SOURCE_DIR}/web
          -DFILES=${web_list} -P ${PROJECT_SOURCE_DIR}/cmake/embed_web.cmake
  DEPENDS ${web_deps} ${PROJECT_SOURCE_DIR}/cmake/embed_web.cmake
  COMMENT "Embedding app/web into brdfnav" VERBATIM)

# What the server gives back when idle and how many heaps it keeps (serve_memory.h): std only.
add_library(brdfnav_serve_memory STATIC serve_memory.cpp)
target_include_directories(brdfnav_serve_memory PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})

# The request handling on its own, compiled once for the server and the fuzzer of tests/fuzz.
add_library(brdfnav_serve_api STATIC serve_api.cpp serve_rings.cpp)
target_include_directories(brdfnav_serve_api PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(brdfnav_serve_api PUBLIC brdfnav::navigator_cxx brdfnav::precompute brdfnav::ocio
                                               brdfnav_exact_thumbnails brdfnav_serve_memory
                      PRIVATE brdfnav_io brdfnav_export nlohmann_json::nlohmann_json
                              OpenImageIO::OpenImageIO)

target_sources(brdfnav_cli PRIVATE cmd_serve.cpp ${web_cpp})
# OpenEXR: serve sets its thread pool (it reads the database's images through the navigator).
target_link_libraries(brdfnav_cli PRIVATE brdfnav_serve_api PkgConfig::brdfnav_httplib
                                          nlohmann_json::nlohmann_json OpenEXR::OpenEXR)
