#include "harness/quality/generator_run.hpp"

#include "harness/generators/generator_registry.hpp"
#include "harness/vk/buffer.hpp"
#include "harness/vk/device.hpp"

namespace vsgl {

GeneratorRun run_generator(Device& device, const DeviceView& view, const std::string& name, const QualityConfig& config,
                           uint32_t vsgl_count, float K, uint32_t offset_bits) {
  GeneratorConfig gc;
  gc.vsgl_count = vsgl_count;
  gc.K = K;
  gc.bisection_iterations = config.bisection_iterations;
  gc.kmeans_iterations = config.kmeans_iterations;
  gc.offset_bits = offset_bits;
  gc.pyramid = config.pyramid;
  gc.mipmapping = config.mipmapping;
  GeneratorRun run;
  run.generator = make_generator(name, device, view, gc);
  run_untimed(device, *run.generator);
  run.vsgls = download_vector<VsglRecord>(device, run.generator->vsgls(), run.generator->vsgl_count());
  return run;
}

}  // namespace vsgl
