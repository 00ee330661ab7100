#pragma once
// What `vsgl-bench verify` runs: the sizes and parameters shared by the FIS and k-means checks.
#include <cstdint>

namespace vsgl {

struct VerifyConfig {
  uint32_t camera_vsgls = 2048;     // N of the camera view (the paper's)
  uint32_t light_vsgls = 1024;      // N of the light view
  float K = 1.0f;
  uint32_t bisection_iterations = 12;
  uint32_t histogram_samples = 65536;  // kernel centres drawn for the histogram check (capped by the view)
};

}  // namespace vsgl
