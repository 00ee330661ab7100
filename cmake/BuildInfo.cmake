# The build's provenance, generated at build time (harness/core/build_info.hpp, DESIGN.md §9):
# every build re-reads the commit and the dirty state of the source tree (cmake/WriteBuildInfo.cmake)
# and rewrites the generated file only when they changed, so a build at another commit records it
# and an unchanged tree rebuilds nothing. A copied binary knows its commit without the checkout.
# -DVSGL_GIT_COMMIT=<sha> names the commit of a tree without git metadata (a source tarball).
set(VSGL_GIT_COMMIT "" CACHE STRING "the commit of a source tree without .git (empty: ask git)")
set(VSGL_BUILD_INFO_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/WriteBuildInfo.cmake)

function(vsgl_build_info target)
  set(out ${CMAKE_CURRENT_BINARY_DIR}/build_info_data.cpp)
  add_custom_target(${target}_build_info
    COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DOUTPUT=${out} -DGIT_COMMIT=${VSGL_GIT_COMMIT}
            -P ${VSGL_BUILD_INFO_SCRIPT}
    BYPRODUCTS ${out}
    COMMENT "Reading the commit of the source tree"
    VERBATIM)
  target_sources(${target} PRIVATE ${out})
  add_dependencies(${target} ${target}_build_info)
endfunction()
