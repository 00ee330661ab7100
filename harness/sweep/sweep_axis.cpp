#include "harness/sweep/sweep_axis.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <set>
#include <stdexcept>
#include <utility>

#include "harness/core/error.hpp"
#include "harness/core/text_format.hpp"

namespace vsgl {
namespace {

struct ParameterInfo {
  SweepParameter parameter;
  const char* name;
  bool whole;      // N, iterations, sizes
  double minimum;  // smallest value allowed
  bool minimum_inclusive;
};

constexpr ParameterInfo kParameters[] = {
    {SweepParameter::kVsgls, "vsgls", true, 1, true},
    {SweepParameter::kCameraVsgls, "camera-vsgls", true, 1, true},
    {SweepParameter::kLightVsgls, "light-vsgls", true, 1, true},
    {SweepParameter::kK, "K", false, 0, false},
    {SweepParameter::kKmeansIterations, "kmeans-iterations", true, 0, true},
    {SweepParameter::kGbuffer, "gbuffer", true, 1, true},
    {SweepParameter::kRsm, "rsm", true, 1, true},
    {SweepParameter::kPdfSharpness, "pdf-sharpness", false, 0, true},
};

const ParameterInfo& info_of(SweepParameter p) {
  for (const auto& i : kParameters)
    if (i.parameter == p) return i;
  throw std::logic_error("unknown sweep parameter");
}

// The whole text as one finite number, else UsageError.
double number_of(const std::string& text, const std::string& axis) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  if (text.empty() || end != begin + text.size() || errno == ERANGE || !std::isfinite(v) ||
      text.find_first_of("xXpP") != std::string::npos)  // no hexadecimal floats
    throw UsageError("--axis " + axis + ": '" + text + "' is not a number");
  return v;
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t at = text.find(sep, start);
    out.push_back(text.substr(start, at == std::string::npos ? std::string::npos : at - start));
    if (at == std::string::npos) return out;
    start = at + 1;
  }
}

// A value of the parameter, checked against its range; a whole-number parameter accepts a value
// within 1e-9 of an integer (a geometric step of 2 from 256 lands on whole numbers exactly).
double checked_value(const ParameterInfo& p, double v, const std::string& axis) {
  if (p.whole) {
    const double r = std::round(v);
    if (std::abs(v - r) > 1e-9 * std::max(1.0, std::abs(v)))
      throw UsageError("--axis " + axis + ": " + number_text(v) + " is not a whole number (" + p.name +
                       " takes whole numbers)");
    v = r;
    if (v > 4294967295.0) throw UsageError("--axis " + axis + ": " + number_text(v) + " is too large");
  }
  const bool ok = p.minimum_inclusive ? v >= p.minimum : v > p.minimum;
  if (!ok)
    throw UsageError("--axis " + axis + ": " + number_text(v) + " is out of range (" + p.name + " must be " +
                     (p.minimum_inclusive ? ">= " : "> ") + number_text(p.minimum) + ")");
  return v;
}

// Whole numbers print as integers ("1000000", not "1e+06"), others with 6 significant digits.
AxisValue scalar_value(const ParameterInfo& p, double v) {
  return AxisValue{v, 0, 0, p.whole ? std::to_string(static_cast<uint64_t>(v)) : number_text(v, 6)};
}

AxisValue size_value(uint32_t w, uint32_t h) {
  return AxisValue{static_cast<double>(w) * h, w, h, std::to_string(w) + "x" + std::to_string(h)};
}

// "WxH" -> {W, H}, each a whole number >= 1.
std::pair<double, double> size_of(const std::string& text, const std::string& axis, const ParameterInfo& p) {
  const auto parts = split(text, 'x');
  if (parts.size() != 2) throw UsageError("--axis " + axis + ": '" + text + "' is not a size WxH");
  return {checked_value(p, number_of(parts[0], axis), axis), checked_value(p, number_of(parts[1], axis), axis)};
}

// The values of a range a:b:xF or a:b:+D as numbers (before the parameter's checks).
std::vector<double> range_values(double a, double b, const std::string& step, const std::string& axis) {
  if (step.size() < 2 || (step[0] != 'x' && step[0] != '+'))
    throw UsageError("--axis " + axis + ": the step '" + step + "' must be xF (geometric) or +D (arithmetic)");
  const double s = number_of(step.substr(1), axis);
  if (a > b) throw UsageError("--axis " + axis + ": the range starts above its end");
  std::vector<double> out;
  const double slack = 1e-9 * std::max(1.0, std::abs(b));
  if (step[0] == 'x') {
    if (!(s > 1)) throw UsageError("--axis " + axis + ": a geometric step xF needs F > 1");
    if (!(a > 0)) throw UsageError("--axis " + axis + ": a geometric range needs a start > 0");
    for (double v = a; v <= b + slack; v *= s) {
      out.push_back(v);
      if (out.size() > kMaxAxisValues) break;
    }
  } else {
    if (!(s > 0)) throw UsageError("--axis " + axis + ": an arithmetic step +D needs D > 0");
    for (std::size_t k = 0;; ++k) {
      const double v = a + static_cast<double>(k) * s;
      if (v > b + slack) break;
      out.push_back(v);
      if (out.size() > kMaxAxisValues) break;
    }
  }
  return out;
}

}  // namespace

const char* sweep_parameter_name(SweepParameter p) { return info_of(p).name; }

std::optional<SweepParameter> sweep_parameter_from_name(std::string_view name) {
  for (const auto& i : kParameters)
    if (name == i.name) return i.parameter;
  return std::nullopt;
}

double growth_x(SweepParameter p, const AxisValue& v) {
  switch (p) {
    case SweepParameter::kKmeansIterations:
      return v.value + 1;  // I Lloyd iterations and the final assignment: I + 1 assignment passes
    case SweepParameter::kRsm: return v.value * v.value;  // texels
    default: return v.value;                              // N, K, W·H, gamma (0: not on a log axis)
  }
}

std::string growth_symbol(SweepParameter p) {
  switch (p) {
    case SweepParameter::kVsgls:
    case SweepParameter::kCameraVsgls:
    case SweepParameter::kLightVsgls: return "N";
    case SweepParameter::kK: return "K";
    case SweepParameter::kKmeansIterations: return "(I+1)";
    case SweepParameter::kGbuffer:
    case SweepParameter::kRsm: return "texels";
    case SweepParameter::kPdfSharpness: return "γ";
  }
  return "x";
}

std::string growth_x_title(SweepParameter p) {
  switch (p) {
    case SweepParameter::kVsgls: return "N (VSGLs per view)";
    case SweepParameter::kCameraVsgls: return "N (VSGLs on the camera view)";
    case SweepParameter::kLightVsgls: return "N (VSGLs on the light view)";
    case SweepParameter::kK: return "K (FIS kernel size)";
    case SweepParameter::kKmeansIterations: return "I + 1 (k-means assignment passes)";
    case SweepParameter::kGbuffer: return "G-buffer texels (W·H)";
    case SweepParameter::kRsm: return "RSM texels (side²)";
    case SweepParameter::kPdfSharpness: return "γ (PDF raised to γ)";
  }
  return "x";
}

SweepAxis parse_axis_spec(const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos)
    throw UsageError("--axis '" + text + "': expected NAME=VALUES (e.g. vsgls=256:16384:x2, K=1,2,4, K=1:4:+1)");
  const std::string name = text.substr(0, eq), values = text.substr(eq + 1);
  const ParameterInfo* p = nullptr;
  for (const auto& i : kParameters)
    if (name == i.name) p = &i;
  if (p == nullptr) {
    std::string known;
    for (const auto& i : kParameters) known += (known.empty() ? "" : ", ") + std::string(i.name);
    throw UsageError("--axis " + text + ": unknown parameter '" + name + "' (known: " + known + ")");
  }
  if (values.empty()) throw UsageError("--axis " + text + ": no values");
  SweepAxis axis;
  axis.parameter = p->parameter;
  axis.spec = text;
  const bool size = p->parameter == SweepParameter::kGbuffer;
  const std::vector<std::string> range = split(values, ':');
  if (range.size() == 3) {
    if (size) {
      if (range[2].empty() || range[2][0] != 'x')
        throw UsageError("--axis " + text + ": a G-buffer range must be geometric (WxH:WxH:xF)");
      const auto [w0, h0] = size_of(range[0], text, *p);
      const auto [w1, h1] = size_of(range[1], text, *p);
      // Both sides scale by F; the range ends when either passes its end.
      const std::vector<double> scale = range_values(1, std::min(w1 / w0, h1 / h0), range[2], text);
      for (double f : scale)
        axis.values.push_back(size_value(static_cast<uint32_t>(checked_value(*p, w0 * f, text)),
                                         static_cast<uint32_t>(checked_value(*p, h0 * f, text))));
    } else {
      const double a = number_of(range[0], text), b = number_of(range[1], text);
      for (double v : range_values(a, b, range[2], text))
        axis.values.push_back(scalar_value(*p, checked_value(*p, v, text)));
    }
  } else if (range.size() == 1) {
    for (const std::string& item : split(values, ',')) {
      if (item.empty()) throw UsageError("--axis " + text + ": an empty item in the list");
      if (size) {
        const auto [w, h] = size_of(item, text, *p);
        axis.values.push_back(size_value(static_cast<uint32_t>(w), static_cast<uint32_t>(h)));
      } else {
        axis.values.push_back(scalar_value(*p, checked_value(*p, number_of(item, text), text)));
      }
    }
  } else {
    throw UsageError("--axis " + text + ": expected a list v1,v2,... or a range a:b:xF or a:b:+D");
  }
  if (axis.values.size() > kMaxAxisValues)
    throw UsageError("--axis " + text + ": more than " + std::to_string(kMaxAxisValues) + " values");
  if (axis.values.size() < 2)
    throw UsageError("--axis " + text + ": only one value; an axis needs at least 2 to show a growth");
  std::set<std::string> seen;
  for (const AxisValue& v : axis.values)
    if (!seen.insert(v.text).second) throw UsageError("--axis " + text + ": the value " + v.text + " is given twice");
  return axis;
}

void check_axes(const std::vector<SweepAxis>& axes) {
  if (axes.empty()) throw UsageError("sweep needs at least one --axis");
  const auto sets = [](SweepParameter a, SweepParameter b) {
    if (a == b) return true;
    const auto n = [](SweepParameter p) {
      return p == SweepParameter::kVsgls || p == SweepParameter::kCameraVsgls || p == SweepParameter::kLightVsgls;
    };
    return n(a) && n(b) && (a == SweepParameter::kVsgls || b == SweepParameter::kVsgls);
  };
  for (std::size_t i = 0; i < axes.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (sets(axes[i].parameter, axes[j].parameter))
        throw UsageError("--axis " + axes[j].spec + " and --axis " + axes[i].spec + " both set " +
                         (axes[i].parameter == axes[j].parameter ? std::string(axes[i].name()) : std::string("N")));
}

std::vector<std::vector<std::size_t>> axis_product(const std::vector<SweepAxis>& axes) {
  std::vector<std::vector<std::size_t>> out{{}};
  for (const SweepAxis& axis : axes) {
    std::vector<std::vector<std::size_t>> next;
    for (const auto& prefix : out)
      for (std::size_t v = 0; v < axis.values.size(); ++v) {
        next.push_back(prefix);
        next.back().push_back(v);
      }
    out = std::move(next);
  }
  return out;
}

}  // namespace vsgl
