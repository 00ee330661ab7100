#pragma once
// Whether each generator and each FIS mip strategy runs on a device, and why not (DESIGN.md §9):
// what `vsgl-bench devices --json` reports beside the device's limits. FIS is judged on exactly
// the pipelines it creates (fis_pipelines); a k-means generator on its kernels' SPIR-V with the
// work-group size its host passes bounded by the largest k-means group (kernels/include/
// interface/kmeans.h), so "runs" there means every kernel fits that bound.
#include <string>
#include <vector>

#include "harness/formats/devices_model.hpp"
#include "harness/vk/device_info.hpp"
#include "harness/vk/device_limits.hpp"

namespace vsgl {

// The needs of one embedded kernel under the largest work-group size a host gives it.
PipelineNeeds kernel_needs_bound(const std::string& kernel);
// The needs of every pipeline `generator` creates on the default configuration (FIS: the texture
// path and every mip strategy's pipelines; k-means: kernel_needs_bound of each kernel).
std::vector<PipelineNeeds> generator_pipeline_needs(const std::string& generator);

// Per generator and FIS mip strategy whether it runs on `info` (both empty for an unusable device),
// as the devices document records it (formats/devices_model.hpp).
DeviceSupport device_support(const DeviceInfo& info);

}  // namespace vsgl
