#pragma once
// The generator options, each declared once and added to the commands that take it (`tables`,
// `verify`, `shade`, `quality`, `vsgl-gbench`): --generators, --camera-vsgls, --light-vsgls, --K,
// --iterations, --kmeans-iterations, --pyramid texture|buffer, --mipmapping STRATEGY.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench/cli/option_types.hpp"
#include "harness/generators/generator_descriptor.hpp"

namespace vsgl::cli {

struct GeneratorOptions {
  std::vector<std::string> generators;           // empty: the caller's default set
  uint32_t camera_vsgls = kPaperCameraVsgls;    // N on the G-buffer (the paper's)
  uint32_t light_vsgls = kPaperLightVsgls;      // N on the RSM (the paper's)
  GeneratorConfig config;                        // K and iterations; vsgl_count is set per view
};

// "a,b": the names with `separator` between them; --generators lists the registry's names so, and a
// command shows its default set of generators with ",".
std::string joined_names(const std::vector<std::string>& names, const std::string& separator = ",");

// --generators G[,G] (names are checked by the run: the registry's message lists them).
CLI::Option* add_generators_option(CLI::App& app, std::vector<std::string>& generators, const std::string& shown_default,
                                   const OptionNames& names = {});
CLI::Option* add_camera_vsgls_option(CLI::App& app, uint32_t& n, const OptionNames& names = {});
CLI::Option* add_light_vsgls_option(CLI::App& app, uint32_t& n, const OptionNames& names = {});
CLI::Option* add_K_option(CLI::App& app, float& K, const OptionNames& names = {});
CLI::Option* add_bisection_iterations_option(CLI::App& app, uint32_t& iterations, const OptionNames& names = {});
CLI::Option* add_kmeans_iterations_option(CLI::App& app, uint32_t& iterations, const OptionNames& names = {});
// --pyramid texture|buffer (DESIGN.md §6.1a).
CLI::Option* add_pyramid_option(CLI::App& app, PyramidPath& pyramid, const OptionNames& names = {});
// --mipmapping single-pass|blit|per-level (unset: the device kind's default).
CLI::Option* add_mipmapping_option(CLI::App& app, std::optional<MipStrategy>& mipmapping, const std::string& description,
                                   const OptionNames& names = {});
// Every option above, into `o`: the timing front ends' set (`tables`, `vsgl-gbench`).
void add_generator_options(CLI::App& app, GeneratorOptions& o, const OptionNames& names = {});

// The check of one --pyramid item and of --mipmapping.
CLI::Validator pyramid_name();
CLI::Validator mipmapping_name();

}  // namespace vsgl::cli
