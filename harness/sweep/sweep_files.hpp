#pragma once
// What `vsgl-bench sweep` writes under OUT (DESIGN.md §10.1), all rendered from the sweep document:
// OUT/sweep.json (to_json, checked against results/schema/sweep.schema.json), OUT/sweep.md
// (sweep_markdown.hpp) and the SVG plots (sweep_plots.hpp). Until the last point, sweep.json is
// rewritten after each point with the points so far and "complete": false, so a run cut short
// keeps what it measured; the complete sweep is written once everything is complete and valid.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/formats/sweep_model.hpp"
#include "harness/sweep/measured_sweep.hpp"
#include "harness/sweep/pdf_independence.hpp"
#include "harness/sweep/sweep_document.hpp"
#include "harness/sweep/sweep_options.hpp"

namespace vsgl {

struct DeviceInfo;

class SweepWriter {
 public:
  // Reads the schema (--schema FILE, else the one built in) and the run's context, which includes
  // the paper's tables, before any measurement, so a bad schema fails in seconds. Throws InputError.
  SweepWriter(const SweepOptions& options, const DeviceInfo& device);

  const SweepContext& context() const { return context_; }

  // The sweep's document, complete and schema-valid, or an error (DeviceError: a number that is
  // not finite or a point without samples; InputError: a document the schema refuses); nothing
  // written.
  SweepModel checked_document(const MeasuredSweep& sweep, const std::vector<SweepFit>& fits,
                              const std::vector<PdfIndependence>& claims) const;

  // After each point: OUT/sweep.json with the points so far ("complete": false), the fits over
  // those points and no claims (they need every value of γ). Nothing before the first point is timed.
  void write_partial(const MeasuredSweep& sweep) const;

  // The complete sweep: the markdown and plots first, sweep.json last, so "complete": true on disk
  // means every file of the sweep is written. Returns the paths written, in that order.
  std::vector<std::filesystem::path> write_complete(
      const SweepModel& document, const std::string& markdown,
      const std::vector<std::pair<std::string, std::string>>& plots) const;

 private:
  const SweepOptions& options_;
  nlohmann::ordered_json schema_;
  SweepContext context_;
};

}  // namespace vsgl
