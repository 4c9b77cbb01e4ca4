# Script of CoreOnly.ProgramsLinkNeitherQtNorGl (tests/CMakeLists.txt): in a build configured with
# SPT_BUILD_EDITOR=OFF and SPT_BUILD_RENDER=OFF, `spt` and the test programs need no Qt, OpenGL,
# EGL or OSMesa library, so that they run on a server that has none.
foreach(program IN LISTS PROGRAMS)
  execute_process(COMMAND ldd ${program} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "ldd ${program}: exit ${code}\n${err}")
  endif()
  string(REGEX MATCHALL "lib(Qt[0-9A-Za-z]*|GL[A-Za-z]*|EGL|OSMesa|glapi)[^ \n]*" found "${out}")
  if(found)
    message(FATAL_ERROR "${program} needs ${found}:\n${out}")
  endif()
endforeach()
