# Fails if a binary imports a gl* symbol, i.e. calls GL without the loader.
# Usage: cmake -DFILES="a|b|c" [-DNM=nm] -P check_no_gl_imports.cmake
# A direct GL call could bind to the wrong library and render a blank image
# (DESIGN.md §4). To show that the check can see imports at all, the files
# together must import a *GetProcAddress function.
if(NOT NM)
  set(NM nm)
endif()
string(REPLACE "|" ";" files "${FILES}")
set(found_loader FALSE)
foreach(f IN LISTS files)
  execute_process(COMMAND ${NM} -D --undefined-only ${f} OUTPUT_VARIABLE out RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${NM} failed on ${f}")
  endif()
  string(REGEX MATCHALL "[ \t\n]gl[A-Z][A-Za-z0-9_]*" direct "${out}")
  if(direct)
    string(REPLACE "\n" "" direct "${direct}")
    message(FATAL_ERROR "${f} calls GL directly:${direct}\nLoad these through the GL function table (render/src/gl_functions.hpp) instead.")
  endif()
  if(out MATCHES "GetProcAddress")
    set(found_loader TRUE)
  endif()
endforeach()
if(NOT found_loader)
  message(FATAL_ERROR "no *GetProcAddress import found in ${FILES}: the check cannot see imports")
endif()
message(STATUS "no direct gl* imports in ${FILES}")
