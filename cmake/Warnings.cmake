# Project-wide warning flags, applied per target through vsgl_warnings().
function(vsgl_warnings target)
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
      -Wno-sign-conversion -Wnon-virtual-dtor -Wold-style-cast -Wcast-align
      -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough
      -Wno-missing-field-initializers)  # Vulkan structs are zero-filled by `Info x{sType}`
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
      # GCC 12 reports -Wrestrict inside libstdc++'s std::string concatenation at -O2
      # (GCC bug 105651, a false positive fixed in GCC 13).
      target_compile_options(${target} PRIVATE -Wno-restrict)
      if(VSGL_PRECOMPILED_HEADERS)
        # Once libstdc++ comes from a precompiled header (cmake/PrecompiledHeaders.cmake), GCC 12
        # no longer treats its inlined std::string code as a system header's and reports the same
        # family of false positives there (-Warray-bounds, -Wstringop-overflow, -Wstringop-overread in `"x" + str`).
        # Only in that build: -DVSGL_PRECOMPILED_HEADERS=OFF keeps both warnings for our code.
        target_compile_options(${target} PRIVATE -Wno-array-bounds -Wno-stringop-overflow -Wno-stringop-overread)
      endif()
    endif()
    if(VSGL_WERROR)
      target_compile_options(${target} PRIVATE -Werror)
    endif()
  endif()
endfunction()
