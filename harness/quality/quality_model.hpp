#pragma once
// The quality JSON ("vsgl-quality", quality_run.hpp) as a typed model: what the markdown and the
// claim verdicts of quality_report.hpp read, parsed once from the document with every missing or
// mistyped field named by its JSON pointer.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

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
  MassSummary mass_over_target;
  CoverageCountsSummary box, eq3;
  CoverageCountsSummary floor_box, floor_eq3;    // lattice_floor
  CoverageCountsSummary excess_box, excess_eq3;  // excess over the floor
};

struct PowerSummary {
  double max_over_mean = 0, p99_over_mean = 0, power_ratio = 0;
};

struct GeneratorQuality {
  std::optional<CoverageSummary> coverage;  // FIS generators only
  PowerSummary power;
};

struct PdfFrequencySummary {
  double relative_variance = 0;
  std::vector<double> fine_share;
  double share_below_kernel = 0, share_below_kernel_side_texels = 0, mean_kernel_side_texels = 0;
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
};

struct AnimatedFlicker {
  double weighted_cv = 0, error_cv = 0, power_relative_stdev = 0;
};

struct KSweepRow {
  double K = 0, weighted_cv = 0;
  ImageErrorSummary error;
  CoverageSummary coverage;
  PowerSummary power;
};

struct QualityClaimRow {
  std::string claim, measure, verdict;
  std::optional<double> fis_tok15, fis_modified;
};

struct QualityModel {
  nlohmann::json schema_version;
  std::string scene;
  std::string capture_path;
  nlohmann::json gbuffer_size, rsm_size;  // [w, h] and [side, side]
  std::string device_name;
  std::string version, git_commit;
  bool git_dirty = false;
  std::vector<std::string> generators;
  nlohmann::json light_vsgls, camera_vsgls, K, frames;  // printed as written
  std::map<std::string, ViewQuality> views;  // "camera_view", "light_view"
  nlohmann::json reference_vpls, reference_rsm_side, reference_rsm_stride, reference_image;  // printed as written
  double reference_power_ratio = 0;
  std::string reference_method;
  std::map<std::string, ImageErrorSummary> reference_error;
  nlohmann::json flicker_image;
  std::map<std::string, StaticFlicker> flicker_static;
  struct Animated {
    nlohmann::json frames;
    std::string sequence, note;
    double reference_weighted_cv = 0;
    std::map<std::string, AnimatedFlicker> generators;
  };
  std::optional<Animated> flicker_animated;
  std::vector<std::pair<std::string, std::vector<KSweepRow>>> k_sweep;  // in the file's order
  std::vector<QualityClaimRow> claims;  // empty before add_claim_verdicts
  std::vector<std::pair<std::string, double>> timings_s;
};

// Throws InputError ("<what>: <pointer>: <problem>").
QualityModel quality_model_from_json(const nlohmann::json& doc, const std::string& what);

}  // namespace vsgl
