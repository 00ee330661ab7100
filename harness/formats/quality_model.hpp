#pragma once
// The quality JSON ("vsgl-quality", quality_run.hpp) as a typed model: what run_quality fills and
// writes with to_json, and what the markdown and the claim verdicts of quality_report.hpp read,
// parsed once from the document with every missing or mistyped field named by its JSON pointer.
// Raw JSON members are provenance and configuration passed through as written.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/formats/claim.hpp"

namespace vsgl {

// Kernel counts n(t) against 1 on one footprint (DESIGN.md §11a); `overlap` on the box floor/excess.
struct CoverageCountsSummary {
  double gap = 0, surplus = 0, count_error = 0, mean_count = 0;
  std::optional<double> overlap;
};

struct MassSummary {
  double mean = 0, stdev = 0, min = 0, max = 0, p99 = 0;  // stdev: sample (n - 1) from schema 3
};

struct CoverageSummary {
  double gap = 0, overlap = 0, gap_plus_overlap = 0;
  uint64_t texels_with_pdf = 0, gap_texels = 0, overlap_texels = 0;
  MassSummary mass_over_target;
  CoverageCountsSummary box, eq3;
  CoverageCountsSummary floor_box, floor_eq3;    // lattice_floor
  CoverageCountsSummary excess_box, excess_eq3;  // excess over the floor
};

struct PowerSummary {
  double max_over_mean = 0, p99_over_mean = 0, power_ratio = 0;
  double sum_vsgl_power = 0, total_flux = 0;
};

struct GeneratorQuality {
  std::optional<CoverageSummary> coverage;  // FIS generators only
  PowerSummary power;
};

struct PdfFrequencySummary {
  double relative_variance = 0;
  std::vector<double> fine_share;
  double share_below_kernel = 0, share_below_kernel_side_texels = 0, mean_kernel_side_texels = 0;
  std::vector<double> detail_energy;
  double mean_square = 0, share_below_8_texels = 0;
  std::string definition;
};

struct ViewQuality {
  nlohmann::json vsgls;  // N, printed as written
  double total_flux = 0;
  std::optional<PdfFrequencySummary> pdf_frequency;
  std::map<std::string, GeneratorQuality> generators;
};

struct ImageErrorSummary {
  double relative_rmse = 0, p99_pixel_error = 0;
};

struct StaticFlicker {
  double weighted_cv = 0, power_stdev = 0, power_relative_stdev = 0;
  uint32_t frames = 0;
};

struct AnimatedFlicker {
  double weighted_cv = 0, error_cv = 0, power_relative_stdev = 0;
};

struct KSweepRow {
  double K = 0, weighted_cv = 0;
  double power_stdev = 0, power_relative_stdev = 0;  // the row's static flicker, as flicker_static
  uint32_t frames = 0;
  ImageErrorSummary error;
  CoverageSummary coverage;
  PowerSummary power;
};

struct QualityModel {
  std::string schema = "vsgl-quality";
  nlohmann::json schema_version;
  std::string scene;
  std::string capture_path;
  nlohmann::json gbuffer_size, rsm_size;  // [w, h] and [side, side]
  nlohmann::json capture_hashes;          // provenance, raw
  std::string device_name, device_driver;
  // The build's provenance, raw (build_json); to_json writes the three typed fields over it.
  nlohmann::json build = nlohmann::json::object();
  std::string version, git_commit;
  bool git_dirty = false;
  std::vector<std::string> generators;
  nlohmann::json light_vsgls, camera_vsgls, K, frames;  // printed as written
  // The rest of "config" (iterations, strides, the sweep's K, definitions), raw; to_json writes
  // the typed configuration fields over it.
  nlohmann::json config_rest = nlohmann::json::object();
  std::map<std::string, ViewQuality> views;  // "camera_view", "light_view"
  nlohmann::json reference_vpls, reference_rsm_side, reference_rsm_stride, reference_image;  // printed as written
  double reference_power_ratio = 0;
  std::string reference_method;
  std::map<std::string, ImageErrorSummary> reference_error;
  nlohmann::json flicker_image;
  uint32_t flicker_gbuffer_stride = 0;
  std::map<std::string, StaticFlicker> flicker_static;
  struct Animated {
    nlohmann::json frames;
    std::string sequence, note, scene;
    std::vector<std::string> frame_content_hashes;
    uint32_t gbuffer_stride = 0, reference_rsm_stride = 0;
    double reference_weighted_cv = 0;
    std::map<std::string, AnimatedFlicker> generators;
  };
  std::optional<Animated> flicker_animated;
  std::vector<std::pair<std::string, std::vector<KSweepRow>>> k_sweep;  // in the file's order
  // ClaimLayout::kQuality: the numbers each claim was judged on (fis_tok15, fis_modified, and a
  // claim's own, such as the Fig. 1 margin) are its `measured`. None before add_claim_verdicts,
  // and then not written.
  std::optional<std::vector<Claim>> claims;
  std::vector<std::pair<std::string, double>> timings_s;
};

// Throws InputError ("<what>: <pointer>: <problem>").
QualityModel quality_model_from_json(const nlohmann::json& doc, const std::string& what);

// The document of `m`: quality_model_from_json(to_json(m)) == m, field for field, and for a
// document the writer wrote, to_json(quality_model_from_json(doc)) == doc.
void to_json(nlohmann::json& j, const QualityModel& m);

}  // namespace vsgl
