#include "harness/quality/quality_reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>

#include "harness/vk/command_stream.hpp"
#include "harness/vk/device.hpp"
#include "harness/core/error.hpp"
#include "harness/capture/view_matrices.hpp"

namespace vsgl {

float rsm_texel_world_area(const ViewImage& rsm, const SpotLightDesc& light, uint32_t x, uint32_t y, uint32_t stride) {
  const glm::vec3 P(rsm.at(kPX, x, y), rsm.at(kPY, x, y), rsm.at(kPZ, x, y));
  const glm::vec3 N(rsm.at(kNX, x, y), rsm.at(kNY, x, y), rsm.at(kNZ, x, y));
  const glm::vec3 to_texel = P - light.position;
  const float d2 = glm::dot(to_texel, to_texel);
  const glm::vec3 dir = to_texel / std::sqrt(d2);
  const float cos_axis = std::max(glm::dot(dir, glm::normalize(light.direction)), 0.0f);
  const float solid_angle = rsm_texel_area(light, rsm.width) * static_cast<float>(stride) * static_cast<float>(stride) *
                            cos_axis * cos_axis * cos_axis;
  const float cos_surface = std::max(std::abs(glm::dot(N, dir)), 0.1f);
  return solid_angle * d2 / cos_surface;
}

std::vector<VsglRecord> reference_vpls(const ViewImage& rsm, const SpotLightDesc& light, uint32_t stride,
                                       VplExtent extent, VplSet set) {
  const glm::vec3 light_position = light.position;
  if (stride == 0) throw InputError("reference: the RSM stride must be at least 1");
  if (rsm.kind != ViewKind::kLight) throw InputError("reference: VPLs come from the RSM (light view)");
  const float area = static_cast<float>(stride) * static_cast<float>(stride);
  std::vector<VsglRecord> vpls;
  for (uint32_t y = 0; y < rsm.height; y += stride)
    for (uint32_t x = 0; x < rsm.width; x += stride) {
      if (rsm.at(kValid, x, y) <= 0.5f) continue;
      if (set == VplSet::kPdfSupport && !(rsm.at(kPdf, x, y) > 0.0f)) continue;
      const glm::vec3 P(rsm.at(kPX, x, y), rsm.at(kPY, x, y), rsm.at(kPZ, x, y));
      const glm::vec3 N(rsm.at(kNX, x, y), rsm.at(kNY, x, y), rsm.at(kNZ, x, y));
      const glm::vec3 d(rsm.at(kDR, x, y), rsm.at(kDG, x, y), rsm.at(kDB, x, y));
      const glm::vec3 s(rsm.at(kSR, x, y), rsm.at(kSG, x, y), rsm.at(kSB, x, y));
      const glm::vec3 flux = d + s;
      if (!(flux.r + flux.g + flux.b > 0.0f)) continue;
      const TexelMoments m =
          texel_moments(true, P, N, d, s, rsm.at(kRoughness, x, y), 1.0f, light_position, /*camera_view=*/false);
      const glm::vec2 centre((static_cast<float>(x) + 0.5f) / static_cast<float>(rsm.width),
                             (static_cast<float>(y) + 0.5f) / static_cast<float>(rsm.height));
      VsglRecord v = vsgl_from_moments(m, area, 0.0f, centre, 1.0f, 1.0f);
      // Tok15's sigma^2 = E|x|^2 - |E x|^2 of a uniform square of area A: A / 12 on each of its two axes.
      const float sigma2 = extent == VplExtent::kPoint
                               ? kMinVariance
                               : std::max(rsm_texel_world_area(rsm, light, x, y, stride) / 6.0f, kMinVariance);
      v.position_variance = glm::vec4(P, sigma2);
      vpls.push_back(v);
    }
  if (vpls.empty())
    throw InputError(std::string("reference: the RSM has no ") +
                     (set == VplSet::kAllLit ? "lit texel" : "lit texel with PDF > 0") + " at stride " +
                     std::to_string(stride));
  return vpls;
}

uint32_t reference_stride(const ViewImage& rsm, uint32_t side) {
  const uint32_t longest = rsm.width > rsm.height ? rsm.width : rsm.height;
  return side == 0 || longest <= side ? 1u : longest / side;
}

ReferenceLadderMetric reference_ladder_metric(std::vector<double> differences) {
  ReferenceLadderMetric m;
  m.differences = std::move(differences);
  const std::vector<double>& e = m.differences;
  if (e.size() < 2) return m;  // one difference has no rate: nothing is decided (DESIGN.md §11a)
  double product = 1.0;
  for (std::size_t i = 0; i + 1 < e.size(); ++i) {
    m.ratios.push_back(e[i + 1] / e[i]);
    product *= m.ratios.back();
  }
  m.rate = std::pow(product, 1.0 / static_cast<double>(m.ratios.size()));
  const double own = e.back();
  // A geometric tail own * (rho + rho^2 + ...); it does not converge for rho >= 1.
  if (std::isfinite(m.rate) && m.rate >= 0.0 && m.rate < 1.0 && std::isfinite(own))
    m.remaining = own * m.rate / (1.0 - m.rate);
  return m;
}

ClaimVerdict judge_side(ClaimSide side, const Interval& interval, double bound, double bound_high) {
  switch (side) {
    case ClaimSide::kBelow: return judge_below(interval, bound);
    case ClaimSide::kAbove: return judge_above(interval, bound);
    case ClaimSide::kWithin: return judge_within(interval, bound, bound_high);
  }
  return judge_below(interval, bound);
}

double reference_movement(double rate, const std::vector<double>& rung_estimates) {
  constexpr double kInfinite = std::numeric_limits<double>::infinity();
  if (!std::isfinite(rate) || !(rate >= 0.0) || !(rate < 1.0) || rung_estimates.size() < 2) return kInfinite;
  double largest = 0.0, weight = 1.0;  // weight = rho^t, t counted from the finest step
  for (std::size_t i = rung_estimates.size() - 1; i > 0; --i) {
    const double step = std::abs(rung_estimates[i] - rung_estimates[i - 1]);
    if (!std::isfinite(step)) return kInfinite;
    largest = std::max(largest, step * weight);
    weight *= rate;
  }
  return largest * rate / (1.0 - rate);
}

namespace {

std::string short_number(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

std::string interval_text(const Interval& iv) {
  return "[" + short_number(iv.low) + ", " + short_number(iv.high) + "]";
}

}  // namespace

ClaimVerdict reference_decides(const ReferenceLadderMetric* ladder, const ReferenceClaim& claim) {
  ClaimVerdict v = claim.finest;
  v.rule +=
      ", decided only where the interval widened by the claim's remaining movement over the reference's "
      "ladder, and the verdict against its stride-2 rung, agree";
  const auto not_converged = [&](const std::string& why) {
    v.outcome = Outcome::kInconclusive;
    v.reason = "reference not converged (" + why + ")";
    return v;
  };
  if (!ladder) return not_converged("no reference ladder");
  if (!claim.finest.interval) return not_converged("no interval against the reference");
  if (ladder->differences.size() < 2)
    return not_converged("no rate: " + std::to_string(ladder->differences.size()) +
                         " successive difference(s) of the rungs, two needed");
  if (!std::isfinite(ladder->rate) || !(ladder->rate < 1.0))
    return not_converged("the reference's rate " + short_number(ladder->rate) + " per doubling: it does not converge");
  if (claim.rung_estimates.size() < 2) return not_converged("no estimate against the stride-2 rung");
  std::string steps;
  for (std::size_t i = 1; i < claim.rung_estimates.size(); ++i)
    steps +=
        (steps.empty() ? "" : ", ") + short_number(std::abs(claim.rung_estimates[i] - claim.rung_estimates[i - 1]));
  const double movement = reference_movement(ladder->rate, claim.rung_estimates);
  const std::string named = "the claim moved " + steps + " over the rungs, rate " + short_number(ladder->rate);
  if (!std::isfinite(movement)) return not_converged(named + ": its remaining movement is not finite");
  if (claim.finest.inconclusive()) return v;  // the interval reaches the bound by itself
  const Interval widened{claim.finest.interval->low - movement, claim.finest.interval->high + movement};
  const ClaimVerdict w = judge_side(claim.side, widened, claim.bound, claim.bound_high);
  if (w.outcome != claim.finest.outcome)
    return not_converged(named + ", remaining " + short_number(movement) + ": the widened interval " +
                         interval_text(widened) + " reaches the bound " +
                         (claim.side == ClaimSide::kWithin
                              ? "of [" + short_number(claim.bound) + ", " + short_number(claim.bound_high) + "]"
                              : short_number(claim.bound)));
  if (!claim.second_rung) return not_converged("no verdict against the stride-2 rung");
  if (claim.second_rung->outcome != claim.finest.outcome)
    return not_converged("the verdicts differ: " + std::string(outcome_text(claim.finest.outcome)) +
                         " against the reference, " + std::string(outcome_text(claim.second_rung->outcome)) +
                         " against its stride-2 rung");
  return v;
}

FixedVsglGenerator::FixedVsglGenerator(Device& device, const std::vector<VsglRecord>& vsgls, std::string name)
    : name_(std::move(name)), count_(static_cast<uint32_t>(vsgls.size())) {
  if (vsgls.empty()) throw InputError(name_ + ": no VSGLs");
  buffer_ = Buffer(device, vsgls.size() * sizeof(VsglRecord), MemoryUsage::kDeviceLocal, name_ + ".vsgls");
  upload(device, buffer_, vsgls.data(), vsgls.size() * sizeof(VsglRecord));
}

void FixedVsglGenerator::record(CommandStream& stream, const std::function<void(VkCommandBuffer)>& boundary) {
  boundary(stream.get());  // no phase: the records were uploaded at construction
}

}  // namespace vsgl
