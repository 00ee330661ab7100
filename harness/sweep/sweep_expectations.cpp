#include "harness/sweep/sweep_expectations.hpp"

#include <utility>

namespace vsgl {
namespace {

GrowthExpectation constant(std::string why) { return GrowthExpectation{0, kConstantTolerance, std::move(why)}; }
GrowthExpectation linear(std::string why) { return GrowthExpectation{1, kLinearTolerance, std::move(why)}; }

bool is_n(SweepParameter p) {
  return p == SweepParameter::kVsgls || p == SweepParameter::kCameraVsgls || p == SweepParameter::kLightVsgls;
}

}  // namespace

bool parameter_touches_view(SweepParameter p, const std::string& view) {
  switch (p) {
    case SweepParameter::kCameraVsgls:
    case SweepParameter::kGbuffer: return view == "camera_view";
    case SweepParameter::kLightVsgls:
    case SweepParameter::kRsm: return view == "light_view";
    default: return true;
  }
}

std::optional<GrowthExpectation> expected_growth(SweepParameter p, GeneratorFamily family, const std::string& view,
                                                 const std::string& phase) {
  const std::string axis = sweep_parameter_name(p);
  if (!parameter_touches_view(p, view)) return constant("the " + view + " does not change along " + axis);
  const bool texels = p == SweepParameter::kGbuffer || p == SweepParameter::kRsm;
  if (family == GeneratorFamily::kFis) {
    if (p == SweepParameter::kKmeansIterations) return constant("FIS has no Lloyd iterations");
    if (p == SweepParameter::kPdfSharpness)
      return constant("FIS does the same work for any PDF: fixed passes, a fixed number of bisection steps");
    if (phase == "additional") {
      if (texels) return linear("additional is one pass over the texels");
      return constant("additional is one pass over the texels, whatever " + axis);
    }
    if (phase == "mipmapping") {
      if (texels) return linear("the mip chain holds about 4/3 of the texels");
      return constant("the mip chain depends on the texels only");
    }
    if (phase == "filtered_sampling") {
      if (is_n(p)) return linear("filtered sampling runs one thread per VSGL: linear in N");
      if (p == SweepParameter::kK)
        return constant("the level choice is a closed form (Tok15) or a fixed number of bisection steps (modified)");
    }
    return std::nullopt;
  }
  // k-means
  if (p == SweepParameter::kK) return constant("k-means does not use K");
  if (p == SweepParameter::kKmeansIterations) {
    if (phase == "cluster_assignment")
      return linear("cluster_assignment runs I Lloyd iterations and the final assignment: linear in I + 1");
    if (phase == "sort" || phase == "sum") return constant(phase + " runs once, after the final assignment");
    return std::nullopt;
  }
  if (texels) {
    if (phase == "cluster_assignment") return linear("every iteration assigns every texel");
    if (phase == "sort") return linear("the sort is over every texel");
    if (phase == "sum")
      return linear("each cluster sums its texels sequentially; at fixed N they grow with the texels");
  }
  return std::nullopt;
}

}  // namespace vsgl
