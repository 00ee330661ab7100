# Shared by package_check.cmake and deb_check.cmake: `cpack -G <generator>` of the build into a
# fresh ${OUT}, which must then hold exactly one file matching <pattern>; its path goes to <out_var>.
# Any failure stops the calling script with a message naming the command or the files found.
function(vsgl_cpack_one_package generator pattern out_var)
  file(REMOVE_RECURSE "${OUT}")
  execute_process(COMMAND "${CPACK}" -G ${generator} --config "${BUILD_DIR}/CPackConfig.cmake" -B "${OUT}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cpack -G ${generator} failed (${rc}):\n${out}${err}")
  endif()
  file(GLOB found "${OUT}/${pattern}")
  list(LENGTH found count)
  if(NOT count EQUAL 1)
    message(FATAL_ERROR "expected one ${pattern} in ${OUT}, found [${found}]")
  endif()
  set(${out_var} "${found}" PARENT_SCOPE)
endfunction()
