#pragma once
// The k-means half of `vsgl-bench verify` (DESIGN.md §11): kmeans_2d and kmeans_3d on both views of a
// capture, each property checked against the CPU on the device's own intermediate results.
#include <vector>

#include "harness/capture/capture.hpp"
#include "harness/verify/check_result.hpp"
#include "harness/verify/verify_config.hpp"

namespace vsgl {

class Device;

// Assignment (nearest centre = brute force, checked on every `assignment_stride`-th texel), sort
// (the stable permutation and each cluster's range), per-cluster sums (against double sums of the
// same texels), total power (= the clustered texels' flux) and cluster membership (with the
// cluster-size statistics in its detail line).
std::vector<CheckResult> verify_kmeans(Device& device, const Capture& capture, const VerifyConfig& config,
                                       uint32_t assignment_stride = 7);

}  // namespace vsgl
