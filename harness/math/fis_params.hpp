#pragma once
// The parameters of the FIS generators (DESIGN.md §6.1), shared by the GPU generator and the CPU
// reference.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "harness/core/generator_ids.hpp"

namespace vsgl {

enum class FisVariant { kTok15, kModified };

// The generator id of a variant (core/generator_ids.hpp); the ids are string literals, so their
// data() ends in a '\0'.
inline const char* fis_variant_name(FisVariant variant) {
  return (variant == FisVariant::kTok15 ? kFisTok15 : kFisModified).data();
}

// Where the FIS pyramid lives (DESIGN.md §6.1a): sampled images with hardware trilinear filtering
// (the paper's GPU path, the default for timing) or the storage buffer of DESIGN.md §4 with software
// filtering (bit-exact with the CPU reference).
enum class PyramidPath { kTexture, kBuffer };
// How the texture path builds its mip chain (the buffer path always runs one dispatch per level).
enum class MipStrategy { kSinglePass, kBlit, kPerLevel };

inline const char* pyramid_path_name(PyramidPath p) { return p == PyramidPath::kTexture ? "texture" : "buffer"; }
inline const char* mip_strategy_name(MipStrategy m) {
  return m == MipStrategy::kSinglePass ? "single-pass" : m == MipStrategy::kBlit ? "blit" : "per-level";
}
inline std::optional<PyramidPath> parse_pyramid_path(std::string_view s) {
  if (s == "texture") return PyramidPath::kTexture;
  if (s == "buffer") return PyramidPath::kBuffer;
  return std::nullopt;
}
inline std::optional<MipStrategy> parse_mip_strategy(std::string_view s) {
  if (s == "single-pass") return MipStrategy::kSinglePass;
  if (s == "blit") return MipStrategy::kBlit;
  if (s == "per-level") return MipStrategy::kPerLevel;
  return std::nullopt;
}

// The paper's VSGL counts N per view (its Sec. 5 and Tables 1-2): every default of N, in the
// front ends' options and in the configs, is one of these.
inline constexpr uint32_t kPaperCameraVsgls = 2048;
inline constexpr uint32_t kPaperLightVsgls = 1024;

struct FisParams {
  uint32_t vsgl_count = 0;            // N
  float K = 1.0f;                     // kernel size parameter (the paper's setting is 1)
  uint32_t bisection_iterations = 12;  // modified FIS (Eq. 3)
  uint32_t offset_bits = 0;           // Fibonacci offset o (DESIGN.md §5), as 32-bit fixed point
  PyramidPath pyramid = PyramidPath::kTexture;
  std::optional<MipStrategy> mipmapping;  // texture path; unset = the device kind's default
};

}  // namespace vsgl
