#pragma once
// One untimed generator run for the quality measures (DESIGN.md §11a): a lattice offset and a K on
// an uploaded view, its VSGLs kept on the device for shading and downloaded for the metrics.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "harness/generators/vsgl_generator.hpp"
#include "harness/math/vsgl_math.hpp"
#include "harness/quality/quality_run.hpp"

namespace vsgl {

class Device;
struct DeviceView;

struct GeneratorRun {
  std::unique_ptr<VsglGenerator> generator;
  std::vector<VsglRecord> vsgls;
};

// `name` with the quality run's settings (`config`), `vsgl_count` VSGLs, kernel parameter K and
// lattice offset `offset_bits`.
GeneratorRun run_generator(Device& device, const DeviceView& view, const std::string& name, const QualityConfig& config,
                           uint32_t vsgl_count, float K, uint32_t offset_bits);

}  // namespace vsgl
