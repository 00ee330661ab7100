#include "harness/report/measured_table.hpp"

#include <algorithm>
#include <stdexcept>

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

std::vector<double> generator_totals(const MeasuredTable& t, const std::string& g) {
  return add_samples(need_case(t, g, "camera_view").total_ms, need_case(t, g, "light_view").total_ms);
}

double median_total(const MeasuredTable& t, const std::string& g) { return summarize(generator_totals(t, g)).median; }
double median_view(const MeasuredTable& t, const std::string& g, const std::string& view) {
  return summarize(need_case(t, g, view).total_ms).median;
}

}  // namespace vsgl
