#include "harness/sweep/sweep_files.hpp"

#include <stdexcept>

#include "harness/core/atomic_file.hpp"
#include "harness/core/embedded_files.hpp"
#include "harness/core/error.hpp"
#include "harness/core/json_schema_subset.hpp"
#include "harness/report/paper_tables.hpp"
#include "harness/report/run_context.hpp"
#include "harness/vk/device_info.hpp"

namespace vsgl {
namespace {

// The file's text: the document as to_json writes it, indented by 2, with a final newline.
std::string sweep_json_text(const SweepModel& document) { return to_json(document).dump(2) + "\n"; }

}  // namespace

SweepWriter::SweepWriter(const SweepOptions& options, const DeviceInfo& device)
    : options_(options),
      schema_(json_file_or_built_in(options.schema, kSweepSchemaFile, "the sweep schema", " (use --schema FILE)")) {
  context_.device = device_record(device);
  context_.build = this_build();
  context_.run = run_record(options.tables);
  context_.paper = paper_tables_or_built_in(options.tables.paper_tables);
  context_.informative = device.type == VK_PHYSICAL_DEVICE_TYPE_CPU;
}

SweepModel SweepWriter::checked_document(const MeasuredSweep& sweep, const std::vector<SweepFit>& fits,
                                         const std::vector<PdfIndependence>& claims) const {
  SweepModel document;
  nlohmann::ordered_json doc;
  try {
    document = sweep_document(sweep, fits, context_, claims);
    doc = to_json(document);
    require_finite_numbers(doc);
  } catch (const std::invalid_argument& e) {
    throw DeviceError(std::string("sweep: ") + e.what());
  }
  require_conforming(doc, schema_, "the sweep", file_or_built_in_name(options_.schema, kSweepSchemaFile));
  return document;
}

void SweepWriter::write_partial(const MeasuredSweep& sweep) const {
  if (sweep.points.empty()) return;
  const SweepModel document = checked_document(sweep, sweep_fits(sweep), {});
  std::filesystem::create_directories(options_.out_dir);
  write_text_atomic(options_.out_dir / "sweep.json", sweep_json_text(document));
}

std::vector<std::filesystem::path> SweepWriter::write_complete(
    const SweepModel& document, const std::string& markdown,
    const std::vector<std::pair<std::string, std::string>>& plots) const {
  std::vector<std::pair<std::filesystem::path, std::string>> files;
  files.emplace_back(options_.out_dir / "sweep.md", markdown);
  for (const auto& [name, svg] : plots) files.emplace_back(options_.out_dir / name, svg);
  files.emplace_back(options_.out_dir / "sweep.json", sweep_json_text(document));
  // Nothing of the complete sweep is written until every file is complete and valid.
  std::filesystem::create_directories(options_.out_dir);
  std::vector<std::filesystem::path> written;
  for (const auto& [path, text] : files) {
    write_text_atomic(path, text);
    written.push_back(path);
  }
  return written;
}

}  // namespace vsgl
