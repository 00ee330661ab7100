#pragma once
// Numbers in messages and reports, written one way everywhere.
#include <string>

namespace vsgl {

// `value` with `digits` significant digits, as printf's %.<digits>g does ("1e+39", "0.025").
std::string number_text(double value, int digits = 9);

// `value` with `digits` digits after the point, as printf's %.<digits>f does ("0.025", "12.500").
std::string fixed_text(double value, int digits = 3);

// The current UTC time as ISO 8601 to the second ("2026-12-06T20:43:05Z"): when a run started.
std::string utc_now_text();

}  // namespace vsgl
