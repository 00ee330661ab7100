// libFuzzer target: the sweep JSON loader behind the dashboard's scaling section
// (harness/formats/sweep_model.cpp read_sweep_file) and what the dashboard then draws from a sweep
// that loaded (harness/compare/dashboard_scaling.cpp: the log-log charts and tables). Bad input must
// end in InputError; anything else is a bug, and so is a model whose document (to_json) does not
// read back as itself.
#include <cstdint>
#include <string_view>

#include "fuzz_input_files.hpp"
#include "harness/compare/dashboard_scaling.hpp"
#include "harness/core/error.hpp"
#include "harness/formats/sweep_model.hpp"

namespace {

const vsgl::fuzz::ScratchDir& scratch() {
  static const vsgl::fuzz::ScratchDir dir;
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const auto file = scratch().write("sweep.json", input);
  try {
    vsgl::SweepRun run{"fuzz/sweep.json", vsgl::read_sweep_file(file)};
    (void)vsgl::scaling_section_html({run}, "fuzz");
    const nlohmann::ordered_json doc = vsgl::to_json(run.model);
    if (vsgl::to_json(vsgl::read_sweep_model(doc, "fuzz/sweep.json")) != doc) __builtin_trap();
  } catch (const vsgl::InputError&) {}
  return 0;
}
