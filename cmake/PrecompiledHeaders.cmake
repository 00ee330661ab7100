# Precompiled headers (DESIGN.md §13): the third-party and standard headers that most translation
# units include are parsed once per kind of target, not once per file. nlohmann-json, CLI11 and
# GoogleTest cost 1-3 s of parsing each, in every file that includes them.
#
# The harness is a static library per folder (cmake/Layers.cmake); they all reuse one header built
# once by vsgl_pch, a library of one empty file with the same flags and definitions as a layer
# (GCC refuses a precompiled header built with other definitions; CMake's -Winvalid-pch and
# -Werror then fail the build rather than silently parse everything again). The CLI library and
# the test binary have their own, with CLI11 and GoogleTest added.
option(VSGL_PRECOMPILED_HEADERS "Precompile the heavy third-party headers (faster builds)" ON)

set(VSGL_PCH_COMMON
  <algorithm> <array> <cstdint> <filesystem> <functional> <map> <memory> <optional> <sstream>
  <string> <string_view> <vector> <nlohmann/json.hpp> <vulkan/vulkan.h> <glm/glm.hpp>)

if(VSGL_PRECOMPILED_HEADERS)
  set(anchor ${CMAKE_BINARY_DIR}/vsgl_pch_anchor.cpp)
  file(CONFIGURE OUTPUT ${anchor} CONTENT "// The translation unit that builds the harness's precompiled header.\n")
  add_library(vsgl_pch STATIC ${anchor})
  target_include_directories(vsgl_pch PRIVATE ${PROJECT_SOURCE_DIR})
  target_compile_definitions(vsgl_pch PUBLIC GLM_FORCE_DEPTH_ZERO_TO_ONE GLM_FORCE_RADIANS)
  target_link_libraries(vsgl_pch PRIVATE nlohmann_json::nlohmann_json Vulkan::Vulkan glm::glm)
  vsgl_warnings(vsgl_pch)
  target_precompile_headers(vsgl_pch PRIVATE ${VSGL_PCH_COMMON})
endif()

# vsgl_precompiled_headers(<target> LAYER)           a harness layer: reuses vsgl_pch's
# vsgl_precompiled_headers(<target> [HEADERS <h...>]) its own: the common headers and these
function(vsgl_precompiled_headers target)
  if(NOT VSGL_PRECOMPILED_HEADERS)
    return()
  endif()
  cmake_parse_arguments(ARG "LAYER" "" "HEADERS" ${ARGN})
  if(ARG_LAYER)
    target_precompile_headers(${target} REUSE_FROM vsgl_pch)
  else()
    target_precompile_headers(${target} PRIVATE ${VSGL_PCH_COMMON} ${ARG_HEADERS})
  endif()
endfunction()
