# Run by cpack once per generator (CPACK_PROJECT_CONFIG_FILE, set in cmake/Packaging.cmake).
# For the Debian package: refuse to build one without dpkg-shlibdeps, which CPack would otherwise
# skip silently, leaving a package that declares no dependencies; and add the copyright file and
# the changelog Debian's policy asks for in /usr/share/doc/vsgl-bench.
if(NOT CPACK_GENERATOR STREQUAL "DEB")
  return()
endif()
find_program(VSGL_DPKG_SHLIBDEPS dpkg-shlibdeps)
if(NOT VSGL_DPKG_SHLIBDEPS)
  message(FATAL_ERROR "the .deb needs dpkg-shlibdeps to compute its dependencies: apt-get install dpkg-dev "
                      "(or run cpack -G TGZ for the .tar.gz alone)")
endif()

set(prefix "${CPACK_PACKAGING_INSTALL_PREFIX}")
if(prefix STREQUAL "")
  set(prefix /usr)  # the DEB generator's default
endif()
set(doc ${CPACK_VSGL_WORK_DIR}${prefix}/share/doc/${CPACK_PACKAGE_NAME})
file(REMOVE_RECURSE ${CPACK_VSGL_WORK_DIR})
file(MAKE_DIRECTORY ${doc})
file(WRITE ${doc}/copyright
"${CPACK_PACKAGE_NAME} ${CPACK_PACKAGE_VERSION}

Copyright ${CPACK_VSGL_COPYRIGHT_YEARS} the ${CPACK_PACKAGE_NAME} authors

The ${CPACK_PACKAGE_NAME} source carries no licence statement; this package grants no licence.
")
# A native package's changelog, compressed as Debian's tools do (gzip -9n: no name, no time).
string(TIMESTAMP date "%a, %d %b %Y %H:%M:%S +0000" UTC)
file(WRITE ${doc}/changelog
"${CPACK_PACKAGE_NAME} (${CPACK_PACKAGE_VERSION}) unstable; urgency=medium

  * Built by CPack from the ${CPACK_PACKAGE_NAME} ${CPACK_PACKAGE_VERSION} source tree.

 -- ${CPACK_DEBIAN_PACKAGE_MAINTAINER}  ${date}
")
find_program(VSGL_GZIP gzip)
if(NOT VSGL_GZIP)
  message(FATAL_ERROR "the .deb's changelog needs gzip, which is not installed")
endif()
execute_process(COMMAND ${VSGL_GZIP} -9nf ${doc}/changelog RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gzip -9n of the Debian changelog failed (${rc})")
endif()
# The tree above is copied into the package root as it is.
set(CPACK_INSTALLED_DIRECTORIES "${CPACK_VSGL_WORK_DIR};.")
