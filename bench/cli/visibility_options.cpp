#include "bench/cli/visibility_options.hpp"

#include <bit>
#include <cmath>
#include <cstdint>

#include "bench/cli/option_types.hpp"
#include "harness/core/error.hpp"

namespace vsgl::cli {
namespace {

// A number read by CLI11's own parser (the option's type), checked by `ok`; `rule` says what it must be.
template <class T, class Ok>
CLI::Validator checked_number(Ok ok, const std::string& rule) {
  return CLI::Validator(
      [ok, rule](std::string& text) -> std::string {
        T v{};
        if (!CLI::detail::lexical_cast(text, v) || !ok(v)) return "must be " + rule + ", not '" + text + "'";
        return {};
      },
      rule);
}

}  // namespace

void add_visibility_options(CLI::App& app, VisibilityOptions& o, const std::string& what) {
  app.add_option("--visibility", o.visibility,
                 "what each VSGL's light passes in " + what +
                     " (DESIGN.md §8.1): ism (its imperfect shadow map, as the paper shades), exact (the segment "
                     "to its mean through a BVH of the scene: the control) or none; ism and exact need the "
                     "visibility geometry `record` stores (--visibility-points)")
      ->check(one_of({"none", "ism", "exact"}))
      ->capture_default_str();
  o.ism_options = {
      app.add_option("--ism-side", o.ism.side, "texels per side of each imperfect shadow map (--visibility ism)")
          ->check(
              checked_number<uint32_t>([](uint32_t v) { return v >= 2 && v <= kIsmMaxSide && std::has_single_bit(v); },
                                       "a power of two in [2, " + std::to_string(kIsmMaxSide) + "]"))
          ->capture_default_str(),
      app.add_option("--ism-points-per-map", o.ism.points_per_map,
                     "points of the capture's sampling each map splats, at most the points it holds")
          ->check(at_least(1))
          ->capture_default_str(),
      app.add_option("--ism-bias", o.ism.depth_bias,
                     "relative depth bias: a map texel occludes where its depth is below (1 - bias) x the receiver's "
                     "distance")
          ->check(checked_number<float>([](float v) { return v >= 0.0f && v < 1.0f; }, "a number in [0, 1)"))
          ->capture_default_str(),
      app.add_option("--ism-normal-offset", o.ism.normal_offset,
                     "texel widths (at the receiver's distance) the receiver moves along its normal before the lookup")
          ->check(checked_number<float>([](float v) { return std::isfinite(v) && v >= 0.0f; }, "a finite number >= 0"))
          ->capture_default_str(),
      app.add_option("--ism-pcf-radius", o.ism.pcf_radius, "the lookup averages (2R + 1)^2 taps")
          ->check(checked_number<uint32_t>([](uint32_t v) { return v <= kIsmMaxPcfRadius; },
                                           "a whole number in [0, " + std::to_string(kIsmMaxPcfRadius) + "]"))
          ->capture_default_str(),
  };
}

ShadingVisibilitySettings visibility_settings(const VisibilityOptions& o) {
  ShadingVisibilitySettings s;
  s.mode = parse_shading_visibility(o.visibility);
  s.ism = o.ism;
  if (s.mode != ShadingVisibility::kIsm)
    for (const CLI::Option* option : o.ism_options)
      if (option->count() > 0)
        throw UsageError(option->get_name() + " sets the imperfect shadow maps, which only --visibility ism uses");
  return s;
}

}  // namespace vsgl::cli
