#pragma once
// Fig. 7, the light occluded by the columns (DESIGN.md §11a.2): the VPL reference shaded with and
// without exact visibility (R_v, R_0), the occluded region O the two fix before any generator is
// looked at, R_v's ladder over O, and every generator's static frames shaded with the run's
// visibility (ism, the paper's, or exact), their relative RMSE over O against R_v and its rungs;
// beside them the control, the same VSGLs with exact visibility from their means.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "harness/capture/capture.hpp"
#include "harness/capture/visibility_geometry.hpp"
#include "harness/formats/quality_model.hpp"
#include "harness/quality/quality_run.hpp"
#include "harness/quality/radiance_image.hpp"
#include "harness/quality/shading_visibility.hpp"

namespace vsgl {

class Device;
struct DeviceView;

// O (DESIGN.md §11a.2): the pixels with a surface where visibility removes more than half of the
// unshadowed light, Y_0 - Y_v > 0.5 Y_0, and that are lit at all, Y_0 > 0.05 mean Y_0.
inline constexpr double kOccludedFraction = 0.5;
inline constexpr double kLitFraction = 0.05;
// Fewer pixels than this, or than this share of the surface pixels, in O: no occluded region.
inline constexpr uint64_t kMinOccludedPixels = 50;
inline constexpr double kMinOccludedShare = 0.01;

struct OccludedRegion {
  std::vector<uint8_t> inside;  // per pixel, 1 in O
  uint64_t surface_pixels = 0, occluded_pixels = 0;
  double unshadowed_mean_luminance = 0;  // mean Y_0 over the surface pixels
  double occluded_light_share = 0;       // sum over O of (Y_0 - Y_v) / sum over the surface of Y_0
  // At least kMinOccludedPixels and kMinOccludedShare of the surface pixels.
  bool large_enough() const;
};

// O from the unshadowed reference R_0 and the shadowed one R_v of the same VPLs and pixels. Throws
// InputError for images of different sizes.
OccludedRegion occluded_region(const RadianceImage& unshadowed, const RadianceImage& shadowed);

// sqrt(sum over O of |L - R|^2 / sum over O of |R|^2) over rgb; infinite where R is black over O.
// Throws InputError for images or a region of different sizes.
double region_relative_rmse(const RadianceImage& frame, const RadianceImage& reference,
                            const std::vector<uint8_t>& region);

// What the Fig. 7 measurement reads: the quality run's device, capture, configuration and views,
// the RSM the reference's VPLs come from, the comparison's G-buffer stride, and the capture's
// visibility geometry.
struct OcclusionInputs {
  Device& device;
  const Capture& capture;
  const QualityConfig& config;
  const DeviceView& camera;
  const DeviceView& light;
  const ViewImage& reference_rsm;
  uint32_t error_stride = 1;
  const VisibilityGeometry& geometry;
  std::function<void(const std::string&)> say;
};

struct OcclusionResult {
  OcclusionMeasure measure;
  std::vector<QualityPicture> pictures;  // the references, the frames and their errors, O outlined
};

// The measurement of DESIGN.md §11a.2 with config.visibility (ism or exact; InputError for none).
OcclusionResult measure_occlusion(const OcclusionInputs& in);

}  // namespace vsgl
