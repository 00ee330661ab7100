#pragma once
// The FIS half of `vsgl-bench verify` (SPEC §11): both FIS generators on both views of a capture,
// each pass checked against the CPU reference computed from the same capture.
#include <cstdint>
#include <vector>

#include "harness/capture.hpp"
#include "harness/check_result.hpp"

namespace vsgl {

class Device;

struct VerifyConfig {
  uint32_t camera_vsgls = 2048;     // N of the camera view (the paper's)
  uint32_t light_vsgls = 1024;      // N of the light view
  float K = 1.0f;
  uint32_t bisection_iterations = 12;
  uint32_t histogram_samples = 65536;  // kernel centres drawn for the histogram check (capped by the view)
};

std::vector<CheckResult> verify_fis(Device& device, const Capture& capture, const VerifyConfig& config);

// Tolerance of |sum of VSGL power / total flux - 1| for a generator on a scene (SPEC §11: stated
// per scene, from measurements; see the definition).
double total_power_tolerance(const std::string& scene, const std::string& generator, const std::string& view);

}  // namespace vsgl
