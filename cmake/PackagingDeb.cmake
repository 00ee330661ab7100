# Run by cpack once per generator (CPACK_PROJECT_CONFIG_FILE, set in cmake/Packaging.cmake).
# For the Debian package: refuse to build one without dpkg-shlibdeps, which CPack would otherwise
# skip silently, leaving a package that declares no dependencies; add the copyright file (DEP-5)
# and the changelog Debian's policy asks for in /usr/share/doc/vsgl-bench; leave LICENSE out.
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
# Debian's machine-readable copyright format (DEP-5). The program's own files are Apache-2.0; the
# licence's text is Debian's common licence, which base-files installs on every system.
file(WRITE ${doc}/copyright
"Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/
Upstream-Name: ${CPACK_PACKAGE_NAME}
Upstream-Contact: ${CPACK_DEBIAN_PACKAGE_MAINTAINER}

Files: *
Copyright: ${CPACK_VSGL_COPYRIGHT_YEARS} the ${CPACK_PACKAGE_NAME} authors
License: Apache-2.0
Comment: The programs also hold code of header-only libraries compiled into
 them: nlohmann-json (MIT), GLM (MIT), CLI11 (BSD-3-Clause) and the Vulkan
 headers (Apache-2.0); each one's Debian package's copyright file has its
 licence. The paper's scenes are not in this package (docs/scenes.md).

License: Apache-2.0
 Licensed under the Apache License, Version 2.0 (the \"License\");
 you may not use this file except in compliance with the License.
 You may obtain a copy of the License at
 .
 http://www.apache.org/licenses/LICENSE-2.0
 .
 Unless required by applicable law or agreed to in writing, software
 distributed under the License is distributed on an \"AS IS\" BASIS,
 WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
 See the License for the specific language governing permissions and
 limitations under the License.
 .
 On Debian systems, the complete text of the Apache License, Version 2.0
 can be found in /usr/share/common-licenses/Apache-2.0.
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
# Every install rule but the licence_text component (LICENSE): the copyright file above holds the
# licence, and Debian wants it nowhere else in /usr/share/doc/<package>.
set(CPACK_INSTALL_CMAKE_PROJECTS "${CPACK_VSGL_BUILD_DIR};${CPACK_VSGL_PROJECT_NAME};Unspecified;/")
