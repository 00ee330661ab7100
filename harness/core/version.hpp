#pragma once
// The tool's version, recorded in every capture sidecar and result file.
namespace vsgl {
inline constexpr int kVersionMajor = 0;
inline constexpr int kVersionMinor = 1;
inline constexpr int kVersionPatch = 0;
inline constexpr const char* kVersionString = "0.1.0";
}  // namespace vsgl
