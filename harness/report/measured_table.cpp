#include "harness/report/measured_table.hpp"

#include <algorithm>
#include <stdexcept>

#include "harness/core/generator_ids.hpp"
#include "harness/core/statistics.hpp"

namespace vsgl {

namespace {

const CaseTiming* find_case(const MeasuredTable& t, const std::string& generator, const std::string& view) {
  for (const auto& c : t.timing.cases)
    if (c.generator == generator && c.view == view) return &c;
  return nullptr;
}

}  // namespace

bool has_generator(const MeasuredTable& t, const std::string& g) {
  return std::find(t.generators.begin(), t.generators.end(), g) != t.generators.end();
}

const CaseTiming& need_case(const MeasuredTable& t, const std::string& generator, const std::string& view) {
  const CaseTiming* c = find_case(t, generator, view);
  if (c == nullptr) throw std::logic_error("table " + std::to_string(t.number) + " has no timing of " + generator + " " + view);
  return *c;
}

IterationDispatches iteration_dispatches(const CaseTiming& c) {
  IterationDispatches out;
  out.iterations = static_cast<uint32_t>(c.iteration_dispatches.size());
  uint32_t inside = 0;
  for (uint32_t n : c.iteration_dispatches) {
    if (n != c.iteration_dispatches.front())
      throw std::logic_error(c.generator + " " + c.view + ": its iterations recorded different dispatch counts");
    inside += n;
  }
  if (inside > c.dispatch_count)
    throw std::logic_error(c.generator + " " + c.view + ": more dispatches in iterations than in all");
  out.per_iteration = out.iterations > 0 ? c.iteration_dispatches.front() : 0;
  out.outside = c.dispatch_count - inside;
  return out;
}

std::vector<double> generator_totals(const MeasuredTable& t, const std::string& g) {
  return add_samples(need_case(t, g, "camera_view").total_ms, need_case(t, g, "light_view").total_ms);
}

double median_total(const MeasuredTable& t, const std::string& g) { return summarize(generator_totals(t, g)).median; }
double median_view(const MeasuredTable& t, const std::string& g, const std::string& view) {
  return summarize(need_case(t, g, view).total_ms).median;
}

const std::vector<double>& case_samples(const MeasuredTable& t, const std::string& g, const std::string& view,
                                        const std::string& phase) {
  const CaseTiming& c = need_case(t, g, view);
  if (phase == "total") return c.total_ms;
  for (std::size_t p = 0; p < c.phases.size(); ++p)
    if (c.phases[p] == phase) return c.phase_ms[p];
  throw std::logic_error(g + " has no phase '" + phase + "'");
}

PairedInterval paired_overhead(const MeasuredTable& t, const std::string& view, const std::string& phase) {
  const std::string mod(kFisModified), tok(kFisTok15);
  if (view.empty())
    return paired_interval(subtract_samples(generator_totals(t, mod), generator_totals(t, tok)), kPairedConfidence);
  return paired_interval(subtract_samples(case_samples(t, mod, view, phase), case_samples(t, tok, view, phase)),
                         kPairedConfidence);
}

}  // namespace vsgl
