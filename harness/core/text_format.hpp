#pragma once
// Numbers in messages and reports, written one way everywhere.
#include <string>

namespace vsgl {

// `value` with `digits` significant digits, as printf's %.<digits>g does ("1e+39", "0.025").
std::string number_text(double value, int digits = 9);

}  // namespace vsgl
