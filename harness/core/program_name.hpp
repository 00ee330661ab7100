#pragma once
// The running program's name ("vsgl-bench", "vsgl-gbench", ...), set once by its main(), so that
// a message printed by library code names the program the user ran.
#include <string>

namespace vsgl {

void set_program_name(std::string name);
// "vsgl-bench" until set.
const std::string& program_name();

}  // namespace vsgl
