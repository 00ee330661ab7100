#include "harness/sweep/measured_sweep.hpp"

#include <algorithm>
#include <cstddef>
#include <map>
#include <stdexcept>

#include "harness/core/error.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/sweep/sweep_expectations.hpp"

namespace vsgl {

std::string slice_text(const std::vector<std::pair<std::string, std::string>>& slice) {
  std::string out;
  for (const auto& [name, value] : slice) out += (out.empty() ? "" : ", ") + name + "=" + value;
  return out;
}

std::string point_values_text(const std::vector<SweepAxis>& axes, const std::vector<std::size_t>& value_index) {
  std::string out;
  for (std::size_t a = 0; a < axes.size(); ++a)
    out += (out.empty() ? "" : ", ") + axes[a].name() + "=" + axes[a].values[value_index.at(a)].text;
  return out;
}

const std::vector<double>* find_point_samples(const SweepPointResult& p, const std::string& g, const std::string& view,
                                              const std::string& phase) {
  for (const CaseTiming& c : p.timing.cases) {
    if (c.generator != g || c.view != view) continue;
    if (phase == "total") return &c.total_ms;
    for (std::size_t i = 0; i < c.phases.size(); ++i)
      if (c.phases[i] == phase) return &c.phase_ms[i];
  }
  return nullptr;
}

const std::vector<double>& point_samples(const SweepPointResult& p, const std::string& g, const std::string& view,
                                         const std::string& phase) {
  if (const std::vector<double>* s = find_point_samples(p, g, view, phase)) return *s;
  throw std::logic_error("sweep point has no timing of " + g + " " + view + " " + phase);
}

std::vector<SweepFit> sweep_fits(const MeasuredSweep& s, const GrowthFitOptions& options) {
  std::vector<SweepFit> out;
  if (s.points.empty()) return out;
  // Every case timed anywhere, in the order they first appear: a case beyond the device at some
  // points is fitted over the others.
  std::vector<CaseTiming> cases;
  for (const SweepPointResult& p : s.points)
    for (const CaseTiming& c : p.timing.cases)
      if (std::none_of(cases.begin(), cases.end(),
                       [&](const CaseTiming& k) { return k.generator == c.generator && k.view == c.view; }))
        cases.push_back(c);
  for (std::size_t a = 0; a < s.axes.size(); ++a) {
    const SweepAxis& axis = s.axes[a];
    // Points grouped by the values of the other axes, in the order they first appear.
    std::vector<std::vector<std::size_t>> keys;
    std::map<std::vector<std::size_t>, std::vector<std::size_t>> slices;
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      std::vector<std::size_t> key = s.points[i].value_index;
      key.erase(key.begin() + static_cast<std::ptrdiff_t>(a));
      if (!slices.contains(key)) keys.push_back(key);
      slices[key].push_back(i);
    }
    for (const auto& key : keys) {
      std::vector<std::size_t> members = slices.at(key);
      std::sort(members.begin(), members.end(), [&](std::size_t i, std::size_t j) {
        return axis.values[s.points[i].value_index[a]].value < axis.values[s.points[j].value_index[a]].value;
      });
      std::vector<std::pair<std::string, std::string>> slice;
      for (std::size_t b = 0; b < s.axes.size(); ++b)
        if (b != a)
          slice.emplace_back(s.axes[b].name(), s.axes[b].values[s.points[members.front()].value_index[b]].text);
      for (const CaseTiming& c : cases) {
        std::vector<std::string> phases = c.phases;
        phases.push_back("total");
        const GeneratorFamily family = generator_descriptor(c.generator).family;
        for (const std::string& phase : phases) {
          SweepFit f;
          f.axis = a;
          f.slice = slice;
          f.generator = c.generator;
          f.view = c.view;
          f.phase = phase;
          std::vector<GrowthPoint> growth;
          for (std::size_t i : members) {
            const std::vector<double>* samples = find_point_samples(s.points[i], c.generator, c.view, phase);
            if (samples == nullptr) continue;
            const double x = growth_x(axis.parameter, axis.values[s.points[i].value_index[a]]);
            f.points.push_back(i);
            f.x.push_back(x);
            if (x > 0) growth.push_back(GrowthPoint{x, *samples});
          }
          if (f.points.empty()) continue;
          f.expected = expected_growth(axis.parameter, family, c.view, phase);
          if (growth.size() < 2) {
            // The reason in brackets only where a point was left off the axis (a sweep still running
            // or one with points beyond the device may have just one point to fit).
            f.note = "fewer than 2 points on a log axis" +
                     (growth.size() < f.points.size() ? " (" + axis.name() + " = 0 cannot be drawn on one)" : "");
          } else {
            GrowthFitOptions o = options;
            o.subject = c.generator + " " + c.view + " " + phase + " over " + axis.name();
            try {
              f.fit = fit_growth(growth, o);
            } catch (const InputError& e) {
              f.note = e.what();
            }
          }
          if (f.fit && f.expected) f.judgement = judge_growth(*f.fit, *f.expected, growth_symbol(axis.parameter));
          out.push_back(std::move(f));
        }
      }
    }
  }
  return out;
}

}  // namespace vsgl
