#include "harness/sweep/sweep_options.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "harness/core/error.hpp"
#include "harness/generators/generator_registry.hpp"

namespace vsgl {
namespace {

bool has_axis(const SweepOptions& o, SweepParameter p) {
  return std::any_of(o.axes.begin(), o.axes.end(), [&](const SweepAxis& a) { return a.parameter == p; });
}

void check_generators(const std::vector<std::string>& generators) {
  if (generators.empty()) throw UsageError("no generator to time");
  const auto known = generator_names();
  std::set<std::string> seen;
  for (const auto& g : generators) {
    if (std::find(known.begin(), known.end(), g) == known.end()) generator_sources(g);  // throws naming the known ones
    if (!seen.insert(g).second) throw UsageError("generator " + g + " is asked for twice");
  }
}

}  // namespace

void check_sweep_options(const SweepOptions& o) {
  if (o.out_dir.empty()) throw UsageError("sweep needs an output directory");
  check_axes(o.axes);
  if (o.capture.has_value() == !o.scene.empty())
    throw UsageError("sweep needs exactly one input: --capture DIR or --scene NAME");
  for (SweepParameter p : {SweepParameter::kGbuffer, SweepParameter::kRsm})
    if (has_axis(o, p) && o.capture)
      throw UsageError(std::string("--axis ") + sweep_parameter_name(p) +
                       " records the capture again at each size, which needs --scene NAME, not --capture");
  const TablesOptions& t = o.tables;
  check_generators(t.generators);
  if (t.camera_vsgls == 0 || t.light_vsgls == 0) throw InputError("N = 0: at least one VSGL is needed");
  t.timing.check();
  if (o.time_budget_s && !(std::isfinite(*o.time_budget_s) && *o.time_budget_s > 0))
    throw UsageError("--time-budget must be a positive number of seconds");
  if (o.blocks < 1 || o.blocks > kMaxSweepBlocks)
    throw UsageError("--blocks must be 1 to " + std::to_string(kMaxSweepBlocks) + " (got " + std::to_string(o.blocks) +
                     ")");
}

}  // namespace vsgl
