# Project-wide warning flags, applied per target through vsgl_warnings().
function(vsgl_warnings target)
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
      -Wno-sign-conversion -Wnon-virtual-dtor -Wold-style-cast -Wcast-align -Wnull-dereference
      -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough
      -Wno-missing-field-initializers)  # Vulkan structs are zero-filled by `Info x{sType}`
    if(VSGL_WERROR)
      target_compile_options(${target} PRIVATE -Werror)
    endif()
  endif()
endfunction()
