#include "bench/cli/generator_options.hpp"


namespace vsgl::cli {

GeneratorOptions read_generator_options(Args& args) {
  GeneratorOptions o;
  o.generators = args.list("--generators", "");
  o.camera_vsgls = args.u32("--camera-vsgls", 2048, 1);
  o.light_vsgls = args.u32("--light-vsgls", 1024, 1);
  o.config.K = args.positive_float("--K", 1.0f);
  o.config.bisection_iterations = args.u32("--iterations", 12, 1);
  o.config.kmeans_iterations = args.u32("--kmeans-iterations", 4, 0);
  return o;
}

}  // namespace vsgl::cli
