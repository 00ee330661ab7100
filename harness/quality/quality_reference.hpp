#pragma once
// The reference of the quality metrics (DESIGN.md §11a): every lit RSM texel its own VSGL
// (kernel level 0, a VPL), shaded by the same pass as the generators' VSGLs (DESIGN.md §8 (a)).
//
// Reduced size: instead of recording a second, smaller capture (whose G-buffer pixels would not be
// the generators' pixels), the reference takes every `stride`-th RSM texel in x and y of the
// capture itself (a point-sampled RSM of side ceil(S_rsm / stride): 128^2 from 512^2 with
// stride 4) and scales each VPL's flux by stride^2, the texel area it stands for, so the total
// power matches the full RSM up to the subsampling error. The G-buffer side is reduced by shading
// every k-th pixel (shade_camera_view's stride), the same pixels for the reference and every
// generator.
#include <cstdint>
#include <optional>
#include <vector>

#include "harness/vk/buffer.hpp"
#include "harness/capture/capture.hpp"
#include "harness/core/claim_verdict.hpp"
#include "harness/formats/quality_model.hpp"
#include "harness/generators/vsgl_generator.hpp"
#include "harness/math/vsgl_math.hpp"

namespace vsgl {

class Device;

// How large a reference VPL is.
enum class VplExtent {
  // sigma^2 = the floor 1e-8: a point light (the single-texel moment variance is rounding noise).
  // Its 1/d^2 spikes on receivers next to a VPL dominate any RMSE; used to test the pass against a
  // brute-force point-VPL sum.
  kPoint,
  // sigma^2 = A / 6, A the world-space area the (subsampled) texel stands for: its solid angle
  // seen from the light, dOmega = texel area on the unit image plane * stride^2 * cos^3(theta) (as
  // the recorder computes flux, DESIGN.md §3), times d^2 / max(cos of the surface to the light, 0.1).
  // A / 6 is Tok15's sigma^2 = E|x|^2 - |E x|^2 of a uniform square of area A (A / 12 per axis;
  // DESIGN.md §7: r^2 = 2 sigma^2), so each VPL is the single-texel VSGL of its own footprint: the
  // generators' limit as their kernels shrink to one texel, with the 1/d^2 singularity bounded.
  kTexelFootprint,
};

// Which texels become VPLs (DESIGN.md §11a): every lit texel (the light the scene reflects), or
// only those where the BRSM PDF is positive (the light a FIS generator can place a kernel centre
// on): the error against the second is the generators' own, without the PDF's bias.
enum class VplSet { kAllLit, kPdfSupport };
inline const char* vpl_set_name(VplSet set) { return set == VplSet::kAllLit ? "all_lit" : "pdf_support"; }

// One VPL per RSM texel (x, y) with x % stride == 0, y % stride == 0, valid, with positive flux
// (and, for kPdfSupport, a positive PDF): vsgl_from_moments() of the texel's own moments
// (DESIGN.md §7), position = the texel's, power = its flux * stride^2, sigma^2 per `extent`,
// level 0, centre = the texel centre. Throws InputError for stride 0, a camera view, or no texel.
std::vector<VsglRecord> reference_vpls(const ViewImage& rsm, const SpotLightDesc& light, uint32_t stride,
                                       VplExtent extent, VplSet set = VplSet::kAllLit);

// The world-space area RSM texel (x, y) stands for at `stride` (see VplExtent::kTexelFootprint).
float rsm_texel_world_area(const ViewImage& rsm, const SpotLightDesc& light, uint32_t x, uint32_t y, uint32_t stride);

// The RSM stride that gives a reference RSM of about `side` texels: max(1, rsm side / side);
// 1 (every texel) for side 0.
uint32_t reference_stride(const ViewImage& rsm, uint32_t side);

// One metric's ladder (DESIGN.md §11a *Convergence table*) from its successive differences, the
// coarsest pair of rungs first and the reference's own error (stride 2 against 1) last: the ratios
// of neighbours, the rate rho per doubling of the side (their geometric mean, (last / first)^(1 /
// (n - 1))) and the remaining error eps_inf = own * rho / (1 - rho), a geometric tail. Fewer than
// two differences: no rate (NaN) and eps_inf infinite; rho >= 1 or not finite: eps_inf infinite.
ReferenceLadderMetric reference_ladder_metric(std::vector<double> differences);

// What a claim on an error against the reference is decided on (DESIGN.md §11a *Rule*, schema 7).
// Where a claim says its statistic lies: below `bound`, above it, or inside (bound, bound_high).
enum class ClaimSide { kBelow, kAbove, kWithin };

// The verdict of `side` on an interval (core/claim_verdict.hpp's edge convention).
ClaimVerdict judge_side(ClaimSide side, const Interval& interval, double bound, double bound_high);

struct ReferenceClaim {
  ClaimSide side = ClaimSide::kBelow;
  double bound = 1.0;       // b (the band's low edge for kWithin)
  double bound_high = 1.0;  // the band's high edge (kWithin only)
  ClaimVerdict finest;  // the claim's verdict against the reference (stride 1), with its interval
  // The claim's statistic against every rung of the ladder, coarsest first, the last against the
  // reference itself; the one before it is the stride-2 rung's. Fewer than two: no step measured.
  std::vector<double> rung_estimates;
  std::optional<ClaimVerdict> second_rung;  // the verdict against the stride-2 rung; none: not measured
};

// The claim's remaining movement delta_inf = max_t s_t rho^t * rho / (1 - rho), s_t the steps of
// `rung_estimates` counted from the finest (t = 0: the stride-2 rung to the reference): each step
// shrinking by rho per doubling from where it was measured. Infinite for rho >= 1 or not finite,
// fewer than two estimates, or an estimate that is not finite.
double reference_movement(double rate, const std::vector<double>& rung_estimates);

// The rule of DESIGN.md §11a: `claim.finest` stands only where the metric's ladder has a rate
// rho < 1, the interval widened by delta_inf on each side gives the same verdict, and the verdict
// against the stride-2 rung is the same; otherwise an inconclusive verdict whose reason starts with
// "reference not converged" and names the steps, rho, delta_inf and the widened interval, or the two
// verdicts. An interval that reaches the bound by itself stays inconclusive for its own reason. No
// ladder (null) or no interval: not decided either. The rule text says what was asked.
ClaimVerdict reference_decides(const ReferenceLadderMetric* ladder, const ReferenceClaim& claim);

// A "generator" with a fixed set of VSGLs, uploaded once: it ignores every parameter, so its
// output never changes between frames (the reference, and the zero-flicker test).
class FixedVsglGenerator : public VsglGenerator {
 public:
  // Throws InputError for an empty set.
  FixedVsglGenerator(Device& device, const std::vector<VsglRecord>& vsgls, std::string name);
  std::string name() const override { return name_; }
  std::vector<std::string> phases() const override { return {}; }
  void record(CommandStream& stream, const std::function<void(VkCommandBuffer)>& boundary) override;
  const Buffer& vsgls() const override { return buffer_; }
  uint32_t vsgl_count() const override { return count_; }

 private:
  std::string name_;
  uint32_t count_;
  Buffer buffer_;
};

}  // namespace vsgl
