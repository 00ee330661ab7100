# Install rules and packages (DESIGN.md §13): `cmake --install` puts the three programs in
# <prefix>/bin, their manual pages in <prefix>/share/man/man1 (cmake/ManPages.cmake) and the README,
# LICENSE and NOTICE in <prefix>/share/doc/vsgl-bench; `cpack` turns the same tree into a .tar.gz
# and, on Linux, a Debian package whose run-time dependencies dpkg-shlibdeps computes from the
# binaries (Debian package dpkg-dev).
include(GNUInstallDirs)

set(VSGL_PACKAGE_NAME vsgl-bench)
# The package name, not the CMake project's (vsgl_bench): Debian's /usr/share/doc/<package>.
set(VSGL_INSTALL_DOCDIR ${CMAKE_INSTALL_DATAROOTDIR}/doc/${VSGL_PACKAGE_NAME})

set(VSGL_INSTALLED_PROGRAMS vsgl-bench)
if(TARGET vsgl-gbench)
  list(APPEND VSGL_INSTALLED_PROGRAMS vsgl-gbench vsgl-mipbench)
endif()
install(TARGETS ${VSGL_INSTALLED_PROGRAMS} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/NOTICE DESTINATION ${VSGL_INSTALL_DOCDIR})
# The licence text in a component of its own: the .deb leaves it out (cmake/PackagingDeb.cmake),
# as Debian's copyright file carries the licence there.
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${VSGL_INSTALL_DOCDIR} COMPONENT licence_text)
include(${CMAKE_CURRENT_LIST_DIR}/ManPages.cmake)

# The version the packages carry: the project's, or what ci/release.sh stamps (the latest tag, or
# the project's version plus the commit). A Debian upstream version without a hyphen (a native
# package): it starts with a digit and holds letters, digits and . + ~ only.
set(VSGL_PACKAGE_VERSION ${PROJECT_VERSION} CACHE STRING "the version in the packages' names and metadata")
if(NOT VSGL_PACKAGE_VERSION MATCHES "^[0-9][A-Za-z0-9.+~]*$")
  message(FATAL_ERROR "VSGL_PACKAGE_VERSION '${VSGL_PACKAGE_VERSION}': expected a version that starts with a "
                      "digit and holds letters, digits and . + ~ only (e.g. 0.1.0 or 0.1.0+g1a2b3c4)")
endif()

# A placeholder address (RFC 2606): whoever publishes the package sets their own.
set(VSGL_PACKAGE_MAINTAINER "vsgl-bench maintainers <maintainers@vsgl-bench.example>"
    CACHE STRING "Maintainer field of the Debian package: \"Name <address>\"")

set(CPACK_PACKAGE_NAME ${VSGL_PACKAGE_NAME})
set(CPACK_PACKAGE_VENDOR "vsgl-bench")
set(CPACK_PACKAGE_VERSION ${VSGL_PACKAGE_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Vulkan benchmark of virtual spherical Gaussian light generation")
# Lines of at most 80 characters (Debian's extended description).
set(CPACK_PACKAGE_DESCRIPTION
    "vsgl-bench reproduces the timing tables of Tokuyoshi's Modified Filtered
Importance Sampling for Virtual Spherical Gaussian Lights (2016). It runs four
generators of virtual spherical Gaussian lights on the same recorded inputs,
times every phase with Vulkan timestamp queries and checks every generator
against a CPU reference. It runs on any Vulkan 1.2 device and on Mesa's
lavapipe, a CPU Vulkan driver.")
set(CPACK_PACKAGE_CONTACT "${VSGL_PACKAGE_MAINTAINER}")
set(CPACK_STRIP_FILES ON)
if(WIN32)
  set(CPACK_GENERATOR ZIP)
elseif(APPLE)
  set(CPACK_GENERATOR TGZ)
else()
  set(CPACK_GENERATOR "DEB;TGZ")
endif()

# Debian package: vsgl-bench_<version>_<arch>.deb installing under /usr.
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${VSGL_PACKAGE_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)  # the Vulkan loader, OpenEXR, ... from the binaries
# lavapipe: a device to run on where no GPU driver is installed.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS mesa-vulkan-drivers)
set(CPACK_DEBIAN_PACKAGE_SUGGESTS vulkan-validationlayers)  # --validate
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_DEBIAN_COMPRESSION_TYPE xz)

# Debian wants a copyright file and a changelog in /usr/share/doc/<package>; they describe the
# package, not the program, so cmake/PackagingDeb.cmake (run by cpack for each generator) adds
# them to the .deb alone.
set(CPACK_PROJECT_CONFIG_FILE ${CMAKE_CURRENT_LIST_DIR}/PackagingDeb.cmake)
set(CPACK_VSGL_WORK_DIR ${PROJECT_BINARY_DIR}/package-doc)
set(CPACK_VSGL_BUILD_DIR ${PROJECT_BINARY_DIR})
set(CPACK_VSGL_PROJECT_NAME ${PROJECT_NAME})
set(CPACK_VSGL_COPYRIGHT_YEARS 2026)  # the years of the repository's commits

include(CPack)

# The Windows zip of the three programs (windows-cross preset), named with the same version.
if(WIN32 AND VSGL_BUILD_BENCHMARKS)
  include(${CMAKE_CURRENT_LIST_DIR}/WindowsZip.cmake)
endif()
