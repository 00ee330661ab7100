# `cpack -G DEB` of the build (DESIGN.md §13), then what the .deb holds: the programs, the README,
# NOTICE, the manual pages where the build made them, a changelog, and a copyright file in Debian's
# machine-readable format (DEP-5) that licenses every file under Apache-2.0 with a stand-alone
# licence paragraph naming Debian's copy of its text; LICENSE itself is not there (the copyright
# file carries the licence). Needs dpkg-deb and dpkg-shlibdeps (dpkg-dev): without them it says
# "SKIPPED" (ctest shows the test as skipped, SKIP_REGULAR_EXPRESSION).
# Run by ctest: cmake -DCPACK=cpack -DBUILD_DIR=... -DOUT=... -DMAN_PAGES=a.1.gz,b.1.gz
#                     -DPROGRAMS=a,b -P deb_check.cmake
cmake_minimum_required(VERSION 3.25)  # script mode: today's policies (IN_LIST)

foreach(var CPACK BUILD_DIR OUT MAN_PAGES PROGRAMS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "deb_check.cmake: -D${var}=... is missing")
  endif()
endforeach()
find_program(DPKG_DEB dpkg-deb)
find_program(DPKG_SHLIBDEPS dpkg-shlibdeps)
if(NOT DPKG_DEB OR NOT DPKG_SHLIBDEPS)
  message(STATUS "SKIPPED: the .deb needs dpkg-deb and dpkg-shlibdeps (apt-get install dpkg-dev)")
  return()
endif()

include(${CMAKE_CURRENT_LIST_DIR}/cpack_one_package.cmake)
vsgl_cpack_one_package(DEB "vsgl-bench_*.deb" debs)
set(root "${OUT}/root")
execute_process(COMMAND "${DPKG_DEB}" -x "${debs}" "${root}" RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "dpkg-deb -x ${debs} failed (${rc}): ${err}")
endif()

set(failures "")
set(doc "${root}/usr/share/doc/vsgl-bench")
string(REPLACE "," ";" programs "${PROGRAMS}")
string(REPLACE "," ";" man_pages "${MAN_PAGES}")
set(expected "")
foreach(p IN LISTS programs)
  list(APPEND expected "usr/bin/${p}")
endforeach()
foreach(page IN LISTS man_pages)
  list(APPEND expected "usr/share/man/man1/${page}")
endforeach()
list(APPEND expected usr/share/doc/vsgl-bench/README.md usr/share/doc/vsgl-bench/NOTICE
     usr/share/doc/vsgl-bench/changelog.gz usr/share/doc/vsgl-bench/copyright)
foreach(f IN LISTS expected)
  if(NOT EXISTS "${root}/${f}")
    string(APPEND failures "missing /${f}\n")
  endif()
endforeach()
if(EXISTS "${doc}/LICENSE")
  string(APPEND failures "/usr/share/doc/vsgl-bench/LICENSE is in the .deb: its copyright file carries the licence\n")
endif()

if(EXISTS "${doc}/copyright")
  file(READ "${doc}/copyright" copyright)
  # The header paragraph, then a Files paragraph for every file, then the licence's own paragraph.
  foreach(pattern IN ITEMS
          "^Format: https://www\\.debian\\.org/doc/packaging-manuals/copyright-format/1\\.0/\n"
          "\nUpstream-Name: vsgl-bench\n"
          "\n\nFiles: \\*\nCopyright: [0-9]+[^\n]*\nLicense: Apache-2\\.0\n"
          "\n\nLicense: Apache-2\\.0\n Licensed under the Apache License, Version 2\\.0"
          "\n [^\n]*/usr/share/common-licenses/Apache-2\\.0")
    if(NOT copyright MATCHES "${pattern}")
      string(APPEND failures "the copyright file does not match the DEP-5 pattern '${pattern}'\n")
    endif()
  endforeach()
  if(copyright MATCHES "grants no licen")
    string(APPEND failures "the copyright file still says that no licence is granted\n")
  endif()
endif()

if(failures)
  message(FATAL_ERROR "${debs}:\n${failures}")
endif()
message(STATUS "${debs}: DEP-5 copyright (Apache-2.0), programs [${PROGRAMS}], manual pages [${MAN_PAGES}]")
