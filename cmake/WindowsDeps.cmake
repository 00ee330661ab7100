# The Windows cross build (windows-cross preset, DESIGN.md §13) finds its libraries in
# VSGL_WINDOWS_DEPS, which ci/windows-deps.sh builds from Debian's packages on the first
# configure (minutes; later configures find its stamps and skip it).
execute_process(COMMAND bash ${PROJECT_SOURCE_DIR}/ci/windows-deps.sh ${VSGL_WINDOWS_DEPS}
                RESULT_VARIABLE vsgl_windows_deps_result)
if(NOT vsgl_windows_deps_result EQUAL 0)
  message(FATAL_ERROR "ci/windows-deps.sh could not build the Windows libraries into ${VSGL_WINDOWS_DEPS} (see above)")
endif()
