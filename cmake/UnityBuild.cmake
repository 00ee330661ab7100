# Unity builds (DESIGN.md §13): a target's sources compiled a few at a time as one translation
# unit. The precompiled headers already spare the parsing of the heavy third-party headers; what
# is left in every file is compiling again the same inline code and template instantiations
# (CLI11's App, nlohmann-json's, GoogleTest's), which one unity file does once for its batch.
# Batches stay small enough that both cores of a small machine get work, and that an error still
# points at a few files.
option(VSGL_UNITY_BUILD "Compile sources in small batches as one translation unit (faster builds)" ON)

# vsgl_unity_build(<target> <batch size>)
function(vsgl_unity_build target batch)
  if(VSGL_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${batch})
  endif()
endfunction()
