#include "harness/verify/check_result.hpp"

#include "harness/core/text_format.hpp"

#include <cstdio>
#include <iomanip>
#include <sstream>

namespace vsgl {

std::string format_check(const CheckResult& r) {
  char line[512];
  if (r.measurement) {
    std::snprintf(line, sizeof line, "INFO  %-11s %-14s %-16s %10.5g  (expected %-7.3g) %s", r.view.c_str(),
                  r.generator.c_str(), r.check.c_str(), r.measured, r.expected, r.detail.c_str());
    return line;
  }
  std::snprintf(line, sizeof line, "%s  %-11s %-14s %-16s %10.3g <= %-9.3g %s", r.passed() ? "PASS" : "FAIL",
                r.view.c_str(), r.generator.c_str(), r.check.c_str(), r.measured, r.tolerance, r.detail.c_str());
  return line;
}

std::string check_number(double value, int digits) { return number_text(value, digits); }

}  // namespace vsgl
