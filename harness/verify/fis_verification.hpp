#pragma once
// The FIS half of `vsgl-bench verify` (SPEC §11): both FIS generators on both views of a capture,
// each pass checked against the CPU reference computed from the same capture.
#include <cstdint>
#include <vector>

#include "harness/capture/capture.hpp"
#include "harness/verify/check_result.hpp"
#include "harness/verify/verify_config.hpp"

namespace vsgl {

class Device;


std::vector<CheckResult> verify_fis(Device& device, const Capture& capture, const VerifyConfig& config);

// Tolerance of |sum of VSGL power / total flux - 1| for a generator on a scene (SPEC §11: stated
// per scene, from measurements; see the definition).
double total_power_tolerance(const std::string& scene, const std::string& generator, const std::string& view);

}  // namespace vsgl
