# The Windows package (windows-cross preset, DESIGN.md §13), built with everything else:
# vsgl-bench-<version>-windows-x86_64.zip holding the three programs, the README, LICENSE
# (Apache-2.0) and NOTICE and, in licences/, Debian's copyright file of every library linked into them (ci/windows-deps.sh
# collects them). The programs need no DLL but Windows' own and the GPU driver's vulkan-1.dll.
set(vsgl_zip_name vsgl-bench-${VSGL_PACKAGE_VERSION}-windows-x86_64)
set(vsgl_zip ${CMAKE_BINARY_DIR}/${vsgl_zip_name}.zip)
set(vsgl_zip_stage ${CMAKE_BINARY_DIR}/package/${vsgl_zip_name})
add_custom_command(
  OUTPUT ${vsgl_zip}
  COMMAND ${CMAKE_COMMAND} -E rm -rf ${vsgl_zip_stage} ${vsgl_zip}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${vsgl_zip_stage}
  COMMAND ${CMAKE_COMMAND} -E copy $<TARGET_FILE:vsgl-bench> $<TARGET_FILE:vsgl-gbench> $<TARGET_FILE:vsgl-mipbench>
          ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/NOTICE ${vsgl_zip_stage}
  COMMAND ${CMAKE_COMMAND} -E copy_directory ${VSGL_WINDOWS_DEPS}/licences ${vsgl_zip_stage}/licences
  COMMAND ${CMAKE_COMMAND} -E chdir ${CMAKE_BINARY_DIR}/package
          ${CMAKE_COMMAND} -E tar cf ${vsgl_zip} --format=zip ${vsgl_zip_name}
  DEPENDS vsgl-bench vsgl-gbench vsgl-mipbench ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/LICENSE
          ${PROJECT_SOURCE_DIR}/NOTICE ${VSGL_WINDOWS_DEPS}/stamps/licences
  COMMENT "Windows package ${vsgl_zip_name}.zip"
  VERBATIM)
add_custom_target(vsgl_windows_zip ALL DEPENDS ${vsgl_zip})
