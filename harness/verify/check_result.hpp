#pragma once
// One correctness check of `vsgl-bench verify`: what was measured against what is allowed.
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace vsgl {

struct CheckResult {
  std::string view;       // "camera_view" | "light_view" | "" (device-wide)
  std::string generator;  // "fis_tok15" | ...
  std::string check;      // e.g. "pyramid", "eq3_residual"
  double measured = 0;    // the error (or ratio deviation, or violation count)
  double tolerance = 0;   // passes when measured <= tolerance
  std::string detail;     // what `measured` is, in words, with context numbers
  // A measurement reported beside its expectation, not judged: where no tolerance follows from the
  // maths (an estimator's accuracy on a given scene), none is invented. It never fails.
  bool measurement = false;
  double expected = 0;    // what `measured` is expected to be (measurements only)
  bool passed() const { return measurement || measured <= tolerance; }
};

std::string format_check(const CheckResult& r);  // one aligned line: PASS/FAIL, names, numbers
nlohmann::json to_json(const CheckResult& r);
// A number for a check's detail line, with `digits` significant digits.
std::string check_number(double value, int digits = 3);

}  // namespace vsgl
