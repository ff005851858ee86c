# animator_add_plugin(<target> SOURCES <files...> PROVIDES <id>:<kind> [<id>:<kind>...]
#                     [LINK <libs...>] [OUTPUT_DIRECTORY <dir>])
#
# Builds a plugin library `animator-<...>.so` that exports only `animator_plugin_entry`, and
# writes beside it a manifest (`<library>.plugins`) naming the plugins it provides, so the host
# can find a plugin by id without opening every library. The host checks the manifest against
# the library's descriptors when it opens it. Without PROVIDES no manifest is written, and the
# host opens the library whenever it looks for a plugin it has not found yet.
function(animator_add_plugin target)
  cmake_parse_arguments(P "" "OUTPUT_DIRECTORY" "SOURCES;PROVIDES;LINK" ${ARGN})
  add_library(${target} MODULE ${P_SOURCES})
  set_target_properties(${target} PROPERTIES
    PREFIX ""
    OUTPUT_NAME ${target}
    C_VISIBILITY_PRESET hidden
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  if(ANIMATOR_FUZZ)
    # The fuzz build compiles a plugin's sources into its harness (tests/fuzz/CMakeLists.txt)
    # and never builds the library itself.
    set_target_properties(${target} PROPERTIES EXCLUDE_FROM_ALL ON)
  endif()
  if(P_OUTPUT_DIRECTORY)
    set_target_properties(${target} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${P_OUTPUT_DIRECTORY})
  endif()
  target_link_libraries(${target} PRIVATE animator_sdk ${P_LINK})
  target_link_options(${target} PRIVATE
    "-Wl,--version-script=${CMAKE_SOURCE_DIR}/sdk/plugin.map" "-Wl,--no-undefined")
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${CMAKE_SOURCE_DIR}/sdk/plugin.map)

  if(NOT P_PROVIDES)
    return()
  endif()
  set(manifest "animator-plugin-manifest 1\n")
  foreach(entry IN LISTS P_PROVIDES)
    string(REPLACE ":" " " line "${entry}")
    string(APPEND manifest "${line}\n")
  endforeach()
  file(GENERATE OUTPUT "$<TARGET_FILE:${target}>.plugins" CONTENT "${manifest}")
endfunction()
