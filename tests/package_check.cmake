# `cpack -G TGZ` of the build (DESIGN.md §13), then what the archive lists: one top directory
# holding the programs in <bindir> and the README in <docdir>, and neither the .deb's copyright
# file nor its changelog, which cmake/PackagingDeb.cmake adds to the .deb alone.
# Run by ctest: cmake -DCPACK=cpack -DBUILD_DIR=... -DOUT=... -DBINDIR=bin
#                     -DDOCDIR=share/doc/vsgl-bench -DPROGRAMS=a,b -P package_check.cmake
cmake_minimum_required(VERSION 3.25)  # script mode: today's policies (IN_LIST)

foreach(var CPACK BUILD_DIR OUT BINDIR DOCDIR PROGRAMS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "package_check.cmake: -D${var}=... is missing")
  endif()
endforeach()

file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${CPACK}" -G TGZ --config "${BUILD_DIR}/CPackConfig.cmake" -B "${OUT}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cpack -G TGZ failed (${rc}):\n${out}${err}")
endif()
file(GLOB archives "${OUT}/vsgl-bench-*.tar.gz")
list(LENGTH archives count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "expected one vsgl-bench-*.tar.gz in ${OUT}, found [${archives}]")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -E tar tf "${archives}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE listing ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cannot list ${archives}: ${err}")
endif()
string(REPLACE "\n" ";" entries "${listing}")
get_filename_component(top "${archives}" NAME)
string(REGEX REPLACE "\\.tar\\.gz$" "" top "${top}")

set(failures "")
string(REPLACE "," ";" programs "${PROGRAMS}")
foreach(expected IN LISTS programs)
  if(NOT "${top}/${BINDIR}/${expected}" IN_LIST entries)
    string(APPEND failures "missing ${top}/${BINDIR}/${expected}\n")
  endif()
endforeach()
if(NOT "${top}/${DOCDIR}/README.md" IN_LIST entries)
  string(APPEND failures "missing ${top}/${DOCDIR}/README.md\n")
endif()
foreach(entry IN LISTS entries)
  if(entry MATCHES "/(copyright|changelog\\.gz)$")
    string(APPEND failures "the .deb's ${entry} is in the .tar.gz\n")
  elseif(NOT entry STREQUAL "" AND NOT entry MATCHES "^${top}/")
    string(APPEND failures "${entry} is outside the top directory ${top}/\n")
  endif()
endforeach()
if(failures)
  message(FATAL_ERROR "${archives}:\n${failures}")
endif()
message(STATUS "${archives}:\n${listing}")
