#pragma once
// The axes of `vsgl-bench sweep` (DESIGN.md §10.1): a parameter and the values it takes, written
// `NAME=a:b:xF` (geometric: a, a·F, a·F², ... up to b), `NAME=a:b:+D` (arithmetic) or
// `NAME=v1,v2,...` (a list); G-buffer sizes are WxH. Several axes give their product.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vsgl {

enum class SweepParameter {
  kVsgls,             // N on both views
  kCameraVsgls,       // N on the camera view only
  kLightVsgls,        // N on the light view only
  kK,                 // FIS kernel-size parameter
  kKmeansIterations,  // Lloyd iterations before the final assignment
  kGbuffer,           // G-buffer W x H (the capture is recorded at each)
  kRsm,               // RSM side (the capture is recorded at each)
  kPdfSharpness,      // gamma: both views' PDFs raised to it, on one capture
};

// "vsgls", "camera-vsgls", ..., "pdf-sharpness": the names of --axis.
const char* sweep_parameter_name(SweepParameter parameter);
// The parameter an axis name names (a sweep document's axis); none for an unknown name.
std::optional<SweepParameter> sweep_parameter_from_name(std::string_view name);

struct AxisValue {
  double value = 0;                // the parameter's value (gbuffer: W·H)
  uint32_t width = 0, height = 0;  // gbuffer only
  std::string text;                // as reports print it: "512", "0.5", "960x544"
};

struct SweepAxis {
  SweepParameter parameter = SweepParameter::kVsgls;
  std::string spec;  // as given: "vsgls=256:16384:x2"
  std::vector<AxisValue> values;

  std::string name() const { return sweep_parameter_name(parameter); }
};

// The x of a growth fit at a value (DESIGN.md §10.1): N, K, the assignment passes I + 1, the
// texels W·H or side², gamma. 0 where a log axis cannot hold it (gamma = 0).
double growth_x(SweepParameter parameter, const AxisValue& value);
// How growth_text names x ("N", "K", "(I+1)", "texels", "γ") and how a plot titles it.
std::string growth_symbol(SweepParameter parameter);
std::string growth_x_title(SweepParameter parameter);

inline constexpr std::size_t kMaxAxisValues = 64;

// Throws UsageError naming the problem: no '=', an unknown parameter, a malformed range or list, a
// value out of the parameter's range (N, iterations and sizes are whole numbers; N, K, sizes > 0;
// iterations, gamma >= 0), a step that never reaches the end (F <= 1, D <= 0, a > b), fewer than
// 2 or more than kMaxAxisValues values, a value given twice.
SweepAxis parse_axis_spec(const std::string& text);

// Throws UsageError for no axis, or two axes that set one parameter (vsgls with camera-vsgls or
// light-vsgls counts as that).
void check_axes(const std::vector<SweepAxis>& axes);

// The product of the axes, first axis outermost: each entry holds one value index per axis.
std::vector<std::vector<std::size_t>> axis_product(const std::vector<SweepAxis>& axes);

}  // namespace vsgl
