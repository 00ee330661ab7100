# `cmake --install` into a fresh prefix, then what must land there (DESIGN.md §13): the programs
# alone in <prefix>/<bindir>, the README unchanged in <prefix>/<docdir>, nothing outside bin/ and
# share/ (no static library, header or test binary), and each program starting from there.
# Run by ctest: cmake -DBUILD_DIR=... -DPREFIX=... -DBINDIR=bin -DDOCDIR=share/doc/vsgl-bench
#                     -DPROGRAMS=a,b -DREADME=<source README> -P install_check.cmake
cmake_minimum_required(VERSION 3.25)  # script mode: today's policies (IN_LIST)

foreach(var BUILD_DIR PREFIX BINDIR DOCDIR PROGRAMS README)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "install_check.cmake: -D${var}=... is missing")
  endif()
endforeach()

file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install ${BUILD_DIR} --prefix ${PREFIX} failed (${rc}):\n${out}${err}")
endif()

set(failures "")
# The programs, and nothing else, in bin/.
file(GLOB installed_programs RELATIVE "${PREFIX}/${BINDIR}" "${PREFIX}/${BINDIR}/*")
list(SORT installed_programs)
string(REPLACE "," ";" expected_programs "${PROGRAMS}")
list(SORT expected_programs)
if(NOT installed_programs STREQUAL expected_programs)
  string(APPEND failures "${BINDIR}/ holds [${installed_programs}], expected [${expected_programs}]\n")
endif()

# The README, byte for byte.
set(readme "${PREFIX}/${DOCDIR}/README.md")
if(NOT EXISTS "${readme}")
  string(APPEND failures "${DOCDIR}/README.md was not installed\n")
else()
  file(SHA256 "${readme}" installed_hash)
  file(SHA256 "${README}" source_hash)
  if(NOT installed_hash STREQUAL source_hash)
    string(APPEND failures "${DOCDIR}/README.md differs from ${README}\n")
  endif()
endif()

# Nothing outside bin/ and share/.
file(GLOB_RECURSE everything RELATIVE "${PREFIX}" "${PREFIX}/*")
foreach(f IN LISTS everything)
  if(NOT f MATCHES "^(${BINDIR}|share)/")
    string(APPEND failures "unexpected installed file ${f}\n")
  endif()
endforeach()

# Each installed program starts and prints its help (exit 0).
foreach(program IN LISTS expected_programs)
  set(exe "${PREFIX}/${BINDIR}/${program}")
  if(NOT EXISTS "${exe}")
    continue()
  endif()
  execute_process(COMMAND "${exe}" --help RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    string(APPEND failures "${BINDIR}/${program} --help exited with ${rc}:\n${out}${err}\n")
  elseif(program MATCHES "^vsgl-bench" AND NOT out MATCHES "tables")
    string(APPEND failures "${BINDIR}/${program} --help does not list the tables command:\n${out}\n")
  endif()
endforeach()

if(failures)
  message(FATAL_ERROR "install check in ${PREFIX}:\n${failures}")
endif()
list(LENGTH everything count)
message(STATUS "installed ${count} files into ${PREFIX}: programs [${installed_programs}], README")
