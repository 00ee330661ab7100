#pragma once
// The parameters of the FIS generators (SPEC §6.1), shared by the GPU generator and the CPU
// reference.
#include <cstdint>

namespace vsgl {

enum class FisVariant { kTok15, kModified };

inline const char* fis_variant_name(FisVariant variant) {
  return variant == FisVariant::kTok15 ? "fis_tok15" : "fis_modified";
}

struct FisParams {
  uint32_t vsgl_count = 0;            // N
  float K = 1.0f;                     // kernel size parameter (the paper's setting is 1)
  uint32_t bisection_iterations = 12;  // modified FIS (Eq. 3)
  uint32_t offset_bits = 0;           // Fibonacci offset o (SPEC §5), as 32-bit fixed point
};

}  // namespace vsgl
