#pragma once
// The FIS half of `vsgl-bench verify` (DESIGN.md §11): both FIS generators on both views of a capture,
// each pass checked against the CPU reference computed from the same capture.
#include <cstdint>
#include <vector>

#include "harness/capture/capture.hpp"
#include "harness/verify/check_result.hpp"
#include "harness/verify/verify_config.hpp"

namespace vsgl {

class Device;

// Pass/fail comes from the device against the CPU reference of the same generator on the same
// capture, never from the estimator's accuracy: the sum of VSGL power over the total flux is
// reported as a measurement beside its expectation (CheckResult::measurement).
std::vector<CheckResult> verify_fis(Device& device, const Capture& capture, const VerifyConfig& config);

}  // namespace vsgl
