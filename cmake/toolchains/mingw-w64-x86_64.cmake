# Cross-compiles for Windows x86-64 with Debian's mingw-w64 (g++-mingw-w64-x86-64-posix: the
# POSIX thread model, which std::thread needs). Used by the windows-cross preset and by
# ci/windows-deps.sh for the libraries it builds (DESIGN.md §13).
#
# The libraries come from VSGL_WINDOWS_DEPS (default build/windows-deps), which
# ci/windows-deps.sh fills; the target's own headers and libraries from /usr/x86_64-w64-mingw32.
# Host programs (glslangValidator, ninja) are found on the host.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(VSGL_MINGW_TRIPLE x86_64-w64-mingw32)
set(CMAKE_C_COMPILER ${VSGL_MINGW_TRIPLE}-gcc-posix)
set(CMAKE_CXX_COMPILER ${VSGL_MINGW_TRIPLE}-g++-posix)
set(CMAKE_RC_COMPILER ${VSGL_MINGW_TRIPLE}-windres)

if(NOT VSGL_WINDOWS_DEPS)
  get_filename_component(VSGL_WINDOWS_DEPS "${CMAKE_CURRENT_LIST_DIR}/../../build/windows-deps" ABSOLUTE)
endif()
# try_compile() projects read this file again; they must see the same prefix.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES VSGL_WINDOWS_DEPS)

set(CMAKE_FIND_ROOT_PATH /usr/${VSGL_MINGW_TRIPLE} ${VSGL_WINDOWS_DEPS})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# pkg-config (stb) reads only the prefix's .pc files, never the host's.
set(ENV{PKG_CONFIG_LIBDIR} ${VSGL_WINDOWS_DEPS}/lib/pkgconfig)
set(ENV{PKG_CONFIG_PATH} "")

# Everything static (libstdc++, libgcc, winpthread, the libraries), so the only DLLs a program
# needs are Windows' own and the GPU driver's vulkan-1.dll.
set(CMAKE_EXE_LINKER_FLAGS_INIT -static)
# zlib (for OpenEXR) from libz-mingw-w64-dev: its libz.a, not the import library of zlib1.dll.
set(ZLIB_USE_STATIC_LIBS ON)
# The POSIX gmtime_r/localtime_r, which mingw-w64's <time.h> declares only on request.
set(CMAKE_CXX_FLAGS_INIT -D_POSIX_THREAD_SAFE_FUNCTIONS=200112L)
