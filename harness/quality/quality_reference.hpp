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
#include <vector>

#include "harness/vk/buffer.hpp"
#include "harness/capture/capture.hpp"
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

// The rule of DESIGN.md §11a: a comparison the reference decides is decided only when the
// reference's own error (its stride-2 image against its stride-1 image, relative RMSE) is below a
// tenth of the difference being judged (for example two generators' errors against it); otherwise
// the verdict is "reference not converged". False for a non-finite input.
inline constexpr double kReferenceErrorFactor = 10.0;  // own error x 10 < |difference|
bool reference_decides(double reference_own_error, double judged_difference);

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
