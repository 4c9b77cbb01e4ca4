# Regenerates bundled files (meshes or scenes) and compares them byte for byte with the folder
# holding them. GEN: generator, SRC: bundled folder, OUT: scratch folder, HINT: how to refresh.
file(REMOVE_RECURSE ${OUT}) # files of an earlier generator must not count
execute_process(COMMAND ${GEN} ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${GEN} failed (${rc})")
endif()
file(GLOB generated RELATIVE ${OUT} ${OUT}/*)
file(GLOB bundled RELATIVE ${SRC} ${SRC}/*)
if(NOT generated STREQUAL bundled)
  message(FATAL_ERROR "bundled files (${bundled}) differ from generated (${generated})")
endif()
foreach(f ${generated})
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/${f} ${SRC}/${f} RESULT_VARIABLE diff)
  if(NOT diff EQUAL 0)
    message(FATAL_ERROR "${SRC}/${f} differs from what its generator makes; ${HINT}")
  endif()
endforeach()
