#include "harness/core/program_name.hpp"

namespace vsgl {
namespace {
std::string& stored_name() {
  static std::string name = "vsgl-bench";
  return name;
}
}  // namespace

void set_program_name(std::string name) { stored_name() = std::move(name); }
const std::string& program_name() { return stored_name(); }

}  // namespace vsgl
