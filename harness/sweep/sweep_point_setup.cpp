#include "harness/sweep/sweep_point_setup.hpp"

#include <cstdint>

#include "harness/sweep/measured_sweep.hpp"

namespace vsgl {
namespace {

void apply_value(SweepPointSetup& s, SweepParameter parameter, const AxisValue& v) {
  TablesOptions& t = s.tables;
  const auto whole = static_cast<uint32_t>(v.value);
  switch (parameter) {
    case SweepParameter::kVsgls: t.camera_vsgls = t.light_vsgls = whole; break;
    case SweepParameter::kCameraVsgls: t.camera_vsgls = whole; break;
    case SweepParameter::kLightVsgls: t.light_vsgls = whole; break;
    case SweepParameter::kK: t.generator.K = static_cast<float>(v.value); break;
    case SweepParameter::kKmeansIterations: t.generator.kmeans_iterations = whole; break;
    case SweepParameter::kGbuffer:
      s.sizes.gbuffer_width = v.width;
      s.sizes.gbuffer_height = v.height;
      break;
    case SweepParameter::kRsm: s.sizes.rsm_size = whole; break;
    case SweepParameter::kPdfSharpness: s.gamma = v.value; break;
  }
}

}  // namespace

SweepPointSetup sweep_point_setup(const SweepOptions& o, std::size_t point, const std::vector<std::size_t>& value_index,
                                  std::size_t points) {
  SweepPointSetup s;
  s.point = point;
  s.value_index = value_index;
  s.where = point_values_text(o.axes, value_index);
  s.tables = o.tables;
  s.sizes = o.record_sizes;
  for (std::size_t a = 0; a < o.axes.size(); ++a) apply_value(s, o.axes[a].parameter, o.axes[a].values[value_index[a]]);
  if (o.time_budget_s) s.tables.timing.time_cap_s = *o.time_budget_s / static_cast<double>(points);
  return s;
}

}  // namespace vsgl
