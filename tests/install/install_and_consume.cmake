# Script of Install.ExamplesBuildAndRunAgainstTheInstalledPackage (see CMakeLists.txt).
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)

function(run what)
  cmake_parse_arguments(R "" "EXPECT_CODE;OUTPUT" "COMMAND;MATCH" ${ARGN})
  execute_process(COMMAND ${R_COMMAND} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT DEFINED R_EXPECT_CODE)
    set(R_EXPECT_CODE 0)
  endif()
  if(NOT code EQUAL R_EXPECT_CODE)
    message(FATAL_ERROR "${what}: exit ${code}, expected ${R_EXPECT_CODE}\n${out}\n${err}")
  endif()
  foreach(pattern IN LISTS R_MATCH)
    if(NOT "${out}${err}" MATCHES "${pattern}")
      message(FATAL_ERROR "${what}: output does not match '${pattern}':\n${out}\n${err}")
    endif()
  endforeach()
endfunction()

run("install" COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
set(expected include/spt/spt.hpp include/spt/version.hpp lib/cmake/spt/sptConfig.cmake)
if(WITH_RENDER)
  list(APPEND expected include/spt/render/renderer.hpp)
endif()
foreach(f IN LISTS expected)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "install: ${f} missing")
  endif()
endforeach()
# Private headers stay private.
foreach(f include/spt/sphere_block.hpp include/spt/predicates.hpp include/spt/shapes.hpp)
  if(EXISTS ${prefix}/${f})
    message(FATAL_ERROR "install: private header ${f} was installed")
  endif()
endforeach()

run("configure examples" COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples -B ${WORK_DIR}/build -G ${GENERATOR}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${prefix})
run("build examples" COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build)

set(bin ${WORK_DIR}/build)
set(mesh ${SOURCE_DIR}/resources/meshes/figure.obj)
run("convert_and_print" COMMAND ${bin}/convert_and_print ${mesh} ${WORK_DIR}/figure.spt
    MATCH "figure.obj: [0-9]+ vertices" "tree 'default': [0-9]+ nodes" "1  inner +bounding r=" "wrote ")
# Overlapping copies moving apart along -x: they collide, and the backtrack is positive.
run("query (overlap)" COMMAND ${bin}/query_two_trees ${WORK_DIR}/figure.spt ${WORK_DIR}/figure.spt
    0.05 0 0 1 0 0 0 1 0 0
    MATCH "any: collide" "deepest: depth [0-9]" "backtrack: move B back [0-9.e-]+ along")
run("query (apart)" COMMAND ${bin}/query_two_trees ${WORK_DIR}/figure.spt ${WORK_DIR}/figure.spt 100 0 0
    MATCH "any: apart")
run("query (not a .spt)" COMMAND ${bin}/query_two_trees ${mesh} ${WORK_DIR}/figure.spt EXPECT_CODE 2
    MATCH "figure.obj")

# The Python module, when built: installed in this Python's folder under the prefix, and found there.
if(PYTHON)
  file(GLOB module ${prefix}/${PYTHON_DIR}/spt.*.so)
  if(NOT module)
    message(FATAL_ERROR "install: the Python module is not in ${prefix}/${PYTHON_DIR}")
  endif()
  # (lines, not semicolons, which would split the argument into a CMake list)
  run("import spt" COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${prefix}/${PYTHON_DIR} ${PYTHON} -c
      "import spt\nm = spt.load('${WORK_DIR}/figure.spt')\nprint(spt.__file__, spt.collide(m, m, [[0, 0, 0, 1, 0, 0, 0]])[0])"
      MATCH "^${prefix}/${PYTHON_DIR}/spt[^ ]* True")
endif()
