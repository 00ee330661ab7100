#pragma once
// What `vsgl-bench verify` runs: the sizes and parameters shared by the FIS and k-means checks.
#include <cstdint>
#include <optional>
#include <vector>

#include "harness/math/fis_params.hpp"

namespace vsgl {

struct VerifyConfig {
  uint32_t camera_vsgls = kPaperCameraVsgls;     // N of the camera view (the paper's)
  uint32_t light_vsgls = kPaperLightVsgls;      // N of the light view
  float K = 1.0f;
  uint32_t bisection_iterations = 12;
  uint32_t histogram_samples = 65536;  // kernel centres drawn for the histogram check (capped by the view)
  // FIS pyramid paths checked (DESIGN.md §6.1a), and the texture path's mip strategy for the generator
  // checks (unset: the device kind's default); the pyramid check covers every strategy.
  std::vector<PyramidPath> pyramids{PyramidPath::kTexture, PyramidPath::kBuffer};
  std::optional<MipStrategy> mipmapping;
};

}  // namespace vsgl
