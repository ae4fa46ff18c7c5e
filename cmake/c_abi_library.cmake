# brdfnav_c_abi_library(TARGET EXPORT_NAME NAME COMPONENT COMP SOURCES src... MAP file.map
#                       HEADER include/brdfnav/h.h LIBS lib...)
# A shared library that exports a C ABI and nothing else: hidden visibility, a version script
# (MAP) naming its entry points, every symbol resolved at link time, and an install of the
# library, its C header and its CMake export set brdfnav<Comp>Targets in component COMP. Its
# LIBS are linked privately: a host links nothing else.
function(brdfnav_c_abi_library target)
  cmake_parse_arguments(A "" "EXPORT_NAME;COMPONENT;MAP;HEADER" "SOURCES;LIBS" ${ARGN})
  add_library(${target} SHARED ${A_SOURCES})
  add_library(brdfnav::${A_EXPORT_NAME} ALIAS ${target})
  set_target_properties(${target} PROPERTIES
    EXPORT_NAME ${A_EXPORT_NAME}
    VERSION ${PROJECT_VERSION}
    SOVERSION 0
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON
    LINK_DEPENDS ${A_MAP})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(${target} PRIVATE ${A_LIBS})
  target_link_options(${target} PRIVATE -Wl,--version-script=${A_MAP})
  # A symbol missing from the library fails its link, not a host's dlopen. Clang links its
  # sanitizer runtimes into executables only, so a sanitized library is left with their symbols
  # undefined.
  if(NOT (BRDFNAV_SANITIZE AND CMAKE_CXX_COMPILER_ID STREQUAL "Clang"))
    target_link_options(${target} PRIVATE -Wl,--no-undefined)
  endif()
  string(SUBSTRING ${A_COMPONENT} 0 1 first)
  string(TOUPPER ${first} first)
  string(SUBSTRING ${A_COMPONENT} 1 -1 rest)
  set(export_set brdfnav${first}${rest}Targets)
  install(TARGETS ${target} EXPORT ${export_set}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT ${A_COMPONENT}
    NAMELINK_COMPONENT ${A_COMPONENT})
  install(FILES ${A_HEADER} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/brdfnav
    COMPONENT ${A_COMPONENT})
  install(EXPORT ${export_set} NAMESPACE brdfnav::
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/brdfnav COMPONENT ${A_COMPONENT})
endfunction()
