#pragma once
// One correctness check of `vsgl-bench verify`: what was measured against what is allowed. The
// command writes the checks as the verify document (formats/verify_model.hpp).
#include <string>
#include <vector>

namespace vsgl {

struct CheckResult {
  std::string view;       // "camera_view" | "light_view" | "" (device-wide)
  std::string generator;  // a generator id (core/generator_ids.hpp) or "sampler"; FIS: "<id>[texture/blit]"
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
// A number for a check's detail line, with `digits` significant digits.
std::string check_number(double value, int digits = 3);

}  // namespace vsgl
