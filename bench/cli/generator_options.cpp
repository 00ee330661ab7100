#include "bench/cli/generator_options.hpp"

#include "harness/core/error.hpp"


namespace vsgl::cli {

GeneratorOptions read_generator_options(Args& args) {
  GeneratorOptions o;
  o.generators = args.list("--generators", "");
  o.camera_vsgls = args.u32("--camera-vsgls", 2048, 1);
  o.light_vsgls = args.u32("--light-vsgls", 1024, 1);
  o.config.K = args.positive_float("--K", 1.0f);
  o.config.bisection_iterations = args.u32("--iterations", 12, 1);
  o.config.kmeans_iterations = args.u32("--kmeans-iterations", 4, 0);
  read_pyramid_options(args, o.config);
  return o;
}

PyramidPath parse_pyramid_option(const std::string& value) {
  const auto path = parse_pyramid_path(value);
  if (!path) throw UsageError("--pyramid takes texture or buffer, not '" + value + "'");
  return *path;
}

void read_pyramid_options(Args& args, GeneratorConfig& config) {
  config.pyramid = parse_pyramid_option(args.string("--pyramid", "texture"));
  if (const auto m = args.value("--mipmapping")) {
    config.mipmapping = parse_mip_strategy(*m);
    if (!config.mipmapping) throw UsageError("--mipmapping takes single-pass, blit or per-level, not '" + *m + "'");
  }
}

}  // namespace vsgl::cli
