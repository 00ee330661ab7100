#include "harness/sweep/sweep_run.hpp"

#include "harness/core/path_text.hpp"
#include "harness/core/error.hpp"
#include "harness/sweep/sweep_blocks.hpp"
#include "harness/sweep/sweep_capture_cache.hpp"
#include "harness/sweep/sweep_files.hpp"
#include "harness/sweep/sweep_markdown.hpp"
#include "harness/sweep/sweep_plots.hpp"
#include "harness/sweep/sweep_point_setup.hpp"
#include "harness/sweep/sweep_point_timing.hpp"
#include "harness/vk/device.hpp"

namespace vsgl {
namespace {

// Before any point is timed: what the sweep is of; "complete" stays false until every point is reached.
MeasuredSweep empty_sweep(const SweepOptions& o) {
  MeasuredSweep m;
  m.axes = o.axes;
  m.generators = o.tables.generators;
  m.time_budget_s = o.time_budget_s;
  m.complete = false;
  return m;
}

// A sweep needs 2 points to fit anything; with fewer, the error names what was beyond the device
// and the partial sweep.json that keeps the point timed.
void require_two_points(const MeasuredSweep& m, std::size_t planned, const std::string& device,
                        const std::filesystem::path& out_dir) {
  if (m.points.size() >= 2) return;
  std::string why;
  for (const BeyondDevicePoint& b : m.beyond_device) why += "\n  " + b.reason;
  throw DeviceError("sweep: only " + std::to_string(m.points.size()) + " of " + std::to_string(planned) +
                    " points fit " + device + ", and a sweep needs 2; the others are beyond it:" + why +
                    (m.points.empty() ? std::string()
                                      : "\n" + path_text(out_dir / "sweep.json") +
                                            " keeps the point timed, marked \"complete\": false"));
}

}  // namespace

SweepOutcome run_sweep(Device& device, const SweepOptions& o, const std::function<void(const SweepEvent&)>& on_event) {
  check_sweep_options(o);
  require_timestamps(device.info());
  const std::vector<std::vector<std::size_t>> points = axis_product(o.axes);
  const SweepLog log(on_event, points.size());
  // Everything that is not a measurement first, so a bad schema or scene fails in seconds.
  const SweepWriter writer(o, device.info());
  SweepCaptureCache captures(device, o);

  // Repeated blocks (sweep_blocks.hpp): every block visits every point once, in a drawn order; the
  // budget is shared by all the visits.
  const SweepOrder order = sweep_visit_order(points.size(), o.blocks, o.order_seed);
  MeasuredSweep empty = empty_sweep(o);
  if (o.blocks > 1) empty.order = order;
  PooledSweep pooled(std::move(empty), points.size(), o.blocks > 1);
  for (const std::vector<std::size_t>& block : order.visits)
    for (const std::size_t i : block) {
      if (pooled.beyond_device(i)) continue;
      const SweepPointSetup setup = sweep_point_setup(o, i, points[i], points.size() * o.blocks);
      pooled.add(i, time_sweep_point(device, captures, setup, log));
      writer.write_partial(pooled.sweep());
    }
  MeasuredSweep m = pooled.take();
  require_two_points(m, points.size(), device.info().name, o.out_dir);
  m.complete = true;

  SweepOutcome out;
  out.fits = sweep_fits(m);
  out.claims = judge_pdf_independence(m, out.fits);
  out.document = writer.checked_document(m, out.fits, out.claims);
  out.markdown = sweep_markdown(out.document);
  out.written = writer.write_complete(out.document, out.markdown,
                                      sweep_plots(out.document, &writer.context().paper, m.paper_table));
  out.measured = std::move(m);
  return out;
}

}  // namespace vsgl
