#include "bench/cli/generator_options.hpp"

#include "harness/generators/generator_registry.hpp"

namespace vsgl::cli {

std::string joined_names(const std::vector<std::string>& names, const std::string& separator) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : separator) + n;
  return out;
}

CLI::Validator pyramid_name() { return one_of({"texture", "buffer"}); }
CLI::Validator mipmapping_name() { return one_of({"single-pass", "blit", "per-level"}); }

CLI::Option* add_generators_option(CLI::App& app, std::vector<std::string>& generators, const std::string& shown_default,
                                   const OptionNames& names) {
  return add_list_option(app, names("generators"), generators,
                         "generators to run: " + joined_names(generator_names(), ", "),
                         CLI::Validator([](std::string&) { return std::string(); }, "NAME"))
      ->default_str(shown_default);
}

CLI::Option* add_camera_vsgls_option(CLI::App& app, uint32_t& n, const OptionNames& names) {
  return app.add_option(names("camera-vsgls"), n, "N: VSGLs generated on the camera view (G-buffer)")
      ->check(at_least(1))
      ->capture_default_str();
}

CLI::Option* add_light_vsgls_option(CLI::App& app, uint32_t& n, const OptionNames& names) {
  return app.add_option(names("light-vsgls"), n, "N: VSGLs generated on the light view (RSM)")
      ->check(at_least(1))
      ->capture_default_str();
}

CLI::Option* add_K_option(CLI::App& app, float& K, const OptionNames& names) {
  return app.add_option(names("K"), K, "FIS kernel size parameter K (the paper's Eq. 1; its setting is 1)")
      ->check(positive_number())
      ->capture_default_str();
}

CLI::Option* add_bisection_iterations_option(CLI::App& app, uint32_t& iterations, const OptionNames& names) {
  return app.add_option(names("iterations"), iterations, "bisection steps of the modified FIS's level search (Eq. 3)")
      ->check(at_least(1))
      ->capture_default_str();
}

CLI::Option* add_kmeans_iterations_option(CLI::App& app, uint32_t& iterations, const OptionNames& names) {
  return app.add_option(names("kmeans-iterations"), iterations, "Lloyd iterations of the k-means generators")
      ->check(at_least(0))
      ->capture_default_str();
}

CLI::Option* add_pyramid_option(CLI::App& app, PyramidPath& pyramid, const OptionNames& names) {
  return app
      .add_option_function<std::string>(
          names("pyramid"), [&pyramid](const std::string& text) { pyramid = *parse_pyramid_path(text); },
          "FIS pyramid: texture (sampled images, hardware trilinear, the paper's GPU path) or buffer (storage "
          "buffer, software filter)")
      ->check(pyramid_name())
      ->type_name("P")
      ->default_str(pyramid_path_name(pyramid));
}

CLI::Option* add_mipmapping_option(CLI::App& app, std::optional<MipStrategy>& mipmapping, const std::string& description,
                                   const OptionNames& names) {
  return app
      .add_option_function<std::string>(
          names("mipmapping"), [&mipmapping](const std::string& text) { mipmapping = parse_mip_strategy(text); },
          description)
      ->check(mipmapping_name())
      ->type_name("M")
      ->default_str("the device kind's");
}

void add_generator_options(CLI::App& app, GeneratorOptions& o, const OptionNames& names) {
  add_generators_option(app, o.generators, "all", names);
  add_camera_vsgls_option(app, o.camera_vsgls, names);
  add_light_vsgls_option(app, o.light_vsgls, names);
  add_K_option(app, o.config.K, names);
  add_bisection_iterations_option(app, o.config.bisection_iterations, names);
  add_kmeans_iterations_option(app, o.config.kmeans_iterations, names);
  add_pyramid_option(app, o.config.pyramid, names);
  add_mipmapping_option(app, o.config.mipmapping,
                        "FIS texture path's mip chain: single-pass, blit or per-level (recorded in the JSON)", names);
}

}  // namespace vsgl::cli
