# The heap of spt's own programs (spt, spt-editor, spt-viewer, the benchmarks): a well-kept
# allocator linked into each executable, never into libspt_core, so that a host of the library
# keeps the allocator it chose. docs/benchmarks.md ("Start-up and the programs' heap") measures the choices.
#   SPT_ALLOCATOR=mimalloc  mimalloc 2.0 with large OS pages (transparent huge pages here)
#   SPT_ALLOCATOR=jemalloc  jemalloc 5.3 with thp:always compiled in
#   SPT_ALLOCATOR=system    the C library's malloc
# Builds with a sanitizer keep the system allocator: the sanitizer brings its own.
set(SPT_ALLOCATOR "mimalloc" CACHE STRING "Heap of spt's programs: mimalloc, jemalloc or system")
set_property(CACHE SPT_ALLOCATOR PROPERTY STRINGS mimalloc jemalloc system)
if(NOT SPT_ALLOCATOR MATCHES "^(mimalloc|jemalloc|system)$")
  message(FATAL_ERROR "SPT_ALLOCATOR must be mimalloc, jemalloc or system, not '${SPT_ALLOCATOR}'")
endif()
set(spt_program_allocator ${SPT_ALLOCATOR})
if(CMAKE_CXX_FLAGS MATCHES "-fsanitize=")
  set(spt_program_allocator system)
endif()

if(spt_program_allocator STREQUAL "mimalloc")
  find_package(mimalloc 2.0 REQUIRED)
  add_library(spt_program_allocator OBJECT ${CMAKE_CURRENT_LIST_DIR}/allocator/mimalloc_options.cpp)
  target_link_libraries(spt_program_allocator PUBLIC mimalloc)
elseif(spt_program_allocator STREQUAL "jemalloc")
  find_library(SPT_JEMALLOC_LIBRARY NAMES jemalloc REQUIRED)
  add_library(spt_program_allocator OBJECT ${CMAKE_CURRENT_LIST_DIR}/allocator/jemalloc_options.cpp)
  target_link_libraries(spt_program_allocator PUBLIC ${SPT_JEMALLOC_LIBRARY})
endif()
message(STATUS "spt programs' allocator: ${spt_program_allocator}")

# Links the program allocator into an executable (nothing for `system`).
function(spt_use_program_allocator target)
  if(TARGET spt_program_allocator)
    # An object library linked in puts its object (the options) into the executable itself.
    target_link_libraries(${target} PRIVATE spt_program_allocator)
  endif()
endfunction()
