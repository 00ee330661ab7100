# Manual pages (DESIGN.md §13), included by cmake/Packaging.cmake once the programs exist: help2man
# (Debian package help2man) turns each installed program's own --help into <program>.1 at build
# time, so a page says what the program's help says; each is compressed with gzip -9n (no name, no
# time, as Debian installs manual pages) and installed into <mandir>/man1, hence in the .deb and
# the .tar.gz. VSGL_MAN_PAGES: AUTO makes them where help2man is found and otherwise says that none
# are made (the build and the tests work without them); ON requires help2man (ci/release.sh); OFF
# makes none. A cross build makes none: its programs do not run on the build machine.
# Sets VSGL_MAN_PAGES_MADE and VSGL_MAN_PAGE_FILES (the <program>.1.gz names).
set(VSGL_MAN_PAGES AUTO CACHE STRING "Make the manual pages from the programs' --help with help2man: AUTO, ON or OFF")
set_property(CACHE VSGL_MAN_PAGES PROPERTY STRINGS AUTO ON OFF)
set(VSGL_MAN_PAGES_MADE FALSE)
set(VSGL_MAN_PAGE_FILES "")
if(NOT VSGL_MAN_PAGES MATCHES "^(AUTO|ON|OFF)$")
  message(FATAL_ERROR "VSGL_MAN_PAGES='${VSGL_MAN_PAGES}': expected AUTO, ON or OFF")
endif()

set(why_not "")
if(VSGL_MAN_PAGES STREQUAL "OFF")
  set(why_not "VSGL_MAN_PAGES=OFF")
elseif(CMAKE_CROSSCOMPILING)
  set(why_not "a cross build's programs do not run here to print their --help")
else()
  find_program(VSGL_HELP2MAN help2man)
  find_program(VSGL_MAN_GZIP gzip)
  if(NOT VSGL_HELP2MAN)
    set(why_not "help2man was not found (apt-get install help2man, or bash ci/install-deps.sh)")
  elseif(NOT VSGL_MAN_GZIP)
    set(why_not "gzip was not found")
  endif()
endif()
if(why_not)
  if(VSGL_MAN_PAGES STREQUAL "ON")
    message(FATAL_ERROR "VSGL_MAN_PAGES=ON, but the manual pages cannot be made: ${why_not}")
  endif()
  message(STATUS "Manual pages: not made: ${why_not}")
  return()
endif()

# What each page's NAME line says of its program (help2man --name).
set(vsgl_man_summary_vsgl-bench "Vulkan benchmark of virtual spherical Gaussian light generation")
set(vsgl_man_summary_vsgl-gbench "the vsgl-bench timing cases as Google Benchmark results")
set(vsgl_man_summary_vsgl-mipbench "the FIS mipmapping strategies of vsgl-bench as Google Benchmark results")

set(man_dir ${PROJECT_BINARY_DIR}/man)
set(pages "")
foreach(program IN LISTS VSGL_INSTALLED_PROGRAMS)
  if(NOT DEFINED vsgl_man_summary_${program})
    message(FATAL_ERROR "cmake/ManPages.cmake: no summary for the installed program ${program}")
  endif()
  set(page ${man_dir}/${program}.1)
  add_custom_command(
    OUTPUT ${page}.gz
    COMMAND ${CMAKE_COMMAND} -E make_directory ${man_dir}
    # --version-string: the version without running --version, whose commit line is no version.
    COMMAND ${VSGL_HELP2MAN} --no-info --section=1 --version-string=${PROJECT_VERSION}
            "--name=${vsgl_man_summary_${program}}" --output=${page} $<TARGET_FILE:${program}>
    COMMAND ${VSGL_MAN_GZIP} -9nf ${page}
    DEPENDS ${program}
    COMMENT "Manual page ${program}.1 from ${program} --help"
    VERBATIM)
  list(APPEND pages ${page}.gz)
  list(APPEND VSGL_MAN_PAGE_FILES ${program}.1.gz)
endforeach()
add_custom_target(vsgl_man_pages ALL DEPENDS ${pages})
install(FILES ${pages} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
set(VSGL_MAN_PAGES_MADE TRUE)
message(STATUS "Manual pages: made with ${VSGL_HELP2MAN} for ${VSGL_INSTALLED_PROGRAMS}")
