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
    endif()
    if(VSGL_WERROR)
      target_compile_options(${target} PRIVATE -Werror)
    endif()
  endif()
endfunction()
