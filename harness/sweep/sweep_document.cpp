#include "harness/sweep/sweep_document.hpp"

#include <string>

#include "harness/formats/timing_statistics.hpp"

namespace vsgl {
namespace {

SweepAxisModel axis_model(const SweepAxis& a) {
  SweepAxisModel out{a.name(), a.spec, growth_symbol(a.parameter), growth_x_title(a.parameter), {}};
  for (const AxisValue& v : a.values) {
    SweepAxisValue value{v.text, v.value, growth_x(a.parameter, v), std::nullopt, std::nullopt};
    if (a.parameter == SweepParameter::kGbuffer) {
      value.width = v.width;
      value.height = v.height;
    }
    out.values.push_back(std::move(value));
  }
  return out;
}

SweepCase case_model(const CaseTiming& c) {
  SweepCase out{c.generator, c.view, c.dispatch_count, {}, timing_statistics(c.total_ms)};
  for (std::size_t i = 0; i < c.phases.size(); ++i)
    out.phases.push_back(SweepPhaseTiming{c.phases[i], timing_statistics(c.phase_ms[i])});
  return out;
}

SweepPoint point_model(const SweepPointResult& p, std::size_t index) {
  SweepPoint out;
  out.index = index;
  out.value_index = p.value_index;
  out.capture_dir = p.capture_dir;
  out.capture = p.capture;
  out.config = p.config;
  out.timing = SweepPointTiming{p.time_cap_s,         p.timing.repetitions, p.timing.timed_seconds,
                                p.timing.stop_reason, p.timing.worst_noise, p.block_rounds};
  for (const CaseTiming& c : p.timing.cases) out.cases.push_back(case_model(c));
  if (p.pdf_sharpness) {
    SweepPdfSharpness s;
    s.gamma = *p.pdf_sharpness;
    s.definition =
        "both views' PDFs q raised to gamma, (q / max q)^gamma on the support (valid, q > 0), on a "
        "copy of the capture before upload; pdf_frequency: the Haar spectrum of the result "
        "(DESIGN.md §11a): relative_variance = var(p), fine_share[k] = share of mean(p^2) at "
        "wavelengths below 2^(k+1) texels";
    for (const auto& [view, f] : p.pdf_frequency)
      s.frequency.emplace_back(view, SweepPdfFrequency{f.relative_variance, f.fine_share});
    out.pdf_sharpness = std::move(s);
  }
  return out;
}

SweepFitModel fit_model(const SweepFit& f, const SweepAxis& axis) {
  SweepFitModel out;
  out.axis = f.axis;
  out.slice = f.slice;
  out.generator = f.generator;
  out.view = f.view;
  out.phase = f.phase;
  out.points = f.points;
  out.growth_x = f.x;
  if (f.fit)
    out.growth = SweepGrowth{f.fit->slope,
                             f.fit->low,
                             f.fit->high,
                             f.fit->confidence,
                             f.fit->resamples,
                             f.fit->points,
                             growth_text(*f.fit, growth_symbol(axis.parameter))};
  out.note = f.note;
  if (f.expected) out.expected = SweepExpected{f.expected->slope, f.expected->tolerance, f.expected->why};
  if (f.judgement) {
    out.verdict = f.judgement->verdict;
    out.judgement = f.judgement->text;
  }
  return out;
}

// The paper's claim as its tables file words it (its third claim), else in the harness's words.
std::string pdf_independence_text(const nlohmann::ordered_json& paper) {
  if (paper.is_object() && paper.contains("claims") && paper["claims"].size() > 2)
    return paper["claims"][2].get<std::string>();
  return "FIS cost is almost independent of the PDF, k-means cost is not";
}

}  // namespace

SweepModel sweep_document(const MeasuredSweep& s, const std::vector<SweepFit>& fits, const SweepContext& ctx,
                          const std::vector<PdfIndependence>& claims) {
  SweepModel m;
  m.complete = s.complete;
  m.complete_stated = true;
  m.device = ctx.device;
  m.build = ctx.build;
  m.run = ctx.run;
  m.scene = s.scene;
  m.generators = s.generators;
  for (const SweepAxis& a : s.axes) m.axes.push_back(axis_model(a));
  m.time_budget_s = s.time_budget_s;
  m.time_budget_rule =
      s.order ? "each visit's time cap is the budget / (the number of points x the blocks), a point's the sum over its "
                "visits; the minimum repetitions always run, so a visit may exceed its cap"
              : "each point's time cap is the budget / the number of points; the minimum "
                "repetitions always run, so a point may exceed its cap";
  if (s.order) m.order = SweepOrderModel{s.order->blocks, s.order->seed, s.order->visits};
  m.fit_method =
      "least-squares slope of ln(median ms) over ln(growth_x) along one axis, the other axes "
      "held (a slice); percentile bootstrap over each point's rounds (DESIGN.md §9.1); judged "
      "against the expected slope ± tolerance";
  for (std::size_t i = 0; i < s.points.size(); ++i) m.points.push_back(point_model(s.points[i], i));
  for (const BeyondDevicePoint& b : s.beyond_device)
    m.beyond_device.push_back(SweepBeyondDevice{b.value_index, b.generator, b.view, b.reason});
  for (const SweepFit& f : fits) m.fits.push_back(fit_model(f, s.axes[f.axis]));
  if (!claims.empty()) {
    const std::string text = pdf_independence_text(ctx.paper);
    m.claims.emplace();
    for (const PdfIndependence& c : claims) m.claims->push_back(pdf_independence_claim(c, text, ctx.informative));
  }
  return m;
}

}  // namespace vsgl
