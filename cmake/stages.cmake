# modsynth_stage(NAME [SOURCES ...] [DEPENDS stage ...] [PUBLIC_LIBS ...] [PRIVATE_LIBS ...])
#
# One static library per stage of the pipeline, modsynth_NAME, linked only
# to the stages it builds on (an interface library when it has no SOURCES).
# Its code is src/NAME/ and include/modsynth/NAME/.
#
# Static libraries may depend on each other in a cycle without CMake
# objecting, so the rule is checked where a back edge starts: every
# `#include <modsynth/AREA/...>` in the stage's sources and headers must name
# the stage itself or one it builds on (directly or through others), or
# configuring stops and names the file.
function(modsynth_stage name)
  cmake_parse_arguments(S "" "" "SOURCES;DEPENDS;PUBLIC_LIBS;PRIVATE_LIBS" ${ARGN})
  set(target modsynth_${name})
  # A stage of headers only (value types) has no library to build.
  if(S_SOURCES)
    add_library(${target} STATIC ${S_SOURCES})
    target_compile_options(${target} PRIVATE ${MODSYNTH_WARNINGS})
    set(scope PUBLIC)
  else()
    add_library(${target} INTERFACE)
    set(scope INTERFACE)
  endif()
  target_include_directories(${target} ${scope} ${PROJECT_SOURCE_DIR}/include)
  set(stage_links)
  set(closure ${name})
  foreach(dep IN LISTS S_DEPENDS)
    if(NOT TARGET modsynth_${dep})
      message(FATAL_ERROR "stage ${name} builds on ${dep}, which is not defined yet: define stages in order")
    endif()
    list(APPEND stage_links modsynth_${dep})
    get_property(dep_closure GLOBAL PROPERTY MODSYNTH_STAGE_CLOSURE_${dep})
    list(APPEND closure ${dep_closure})
  endforeach()
  list(REMOVE_DUPLICATES closure)
  set_property(GLOBAL PROPERTY MODSYNTH_STAGE_CLOSURE_${name} ${closure})
  if(S_SOURCES)
    target_link_libraries(${target} PUBLIC ${stage_links} ${S_PUBLIC_LIBS} PRIVATE ${S_PRIVATE_LIBS})
  else()
    target_link_libraries(${target} INTERFACE ${stage_links} ${S_PUBLIC_LIBS})
  endif()

  file(GLOB_RECURSE own_files CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/${name}/*
                                                ${PROJECT_SOURCE_DIR}/include/modsynth/${name}/*.h)
  foreach(file IN LISTS own_files)
    file(STRINGS ${file} includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]modsynth/[a-z_]+/")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE ".*modsynth/([a-z_]+)/.*" "\\1" area "${line}")
      if(NOT area IN_LIST closure)
        file(RELATIVE_PATH shown ${PROJECT_SOURCE_DIR} ${file})
        message(FATAL_ERROR "${shown} includes modsynth/${area}/, but stage ${name} builds only on "
                            "${closure}: a back edge in the stage graph (see cmake/stages.cmake)")
      endif()
    endforeach()
  endforeach()
endfunction()
