#include "bench/cli/command_summaries.hpp"

#include <array>
#include <memory>
#include <sstream>
#include <string>
#include <utility>

namespace vsgl::cli {
namespace {

constexpr std::array<std::pair<std::string_view, std::string_view>, 11> kSummaries{{
    {"devices", "list the Vulkan devices, the default, and what runs on each"},
    {"record", "rasterize a scene preset, procedural scene or glTF/OBJ model into a capture"},
    {"verify", "check every generator on a capture against its CPU reference"},
    {"shade", "the camera view lit by each generator's VSGLs, as PNG (Fig. 5)"},
    {"quality", "the paper's quality claims measured on a capture (Fig. 1, 5, 6)"},
    {"tables", "time the generators: the paper's Tables 1 and 2 on this device"},
    {"frame", "time the paper's frame phase by phase: RSM replay, PDF, VSGLs, ISM, shading"},
    {"sweep", "time the generators along parameter axes and fit their cost growth"},
    {"compare", "FASTER / SLOWER / SAME / AMBIGUOUS verdicts between two runs"},
    {"export", "a run's medians under stable names for github-action-benchmark or Bencher"},
    {"dashboard", "one self-contained HTML page charting every table and sweep"},
}};

// CLI11's formatter, but a command's line in its parent's list is its summary.
class OneLineCommandFormatter : public CLI::Formatter {
 public:
  std::string make_subcommand(const CLI::App* sub) const override {
    const std::string_view summary = command_summary(sub->get_name());
    std::stringstream out;
    CLI::detail::format_help(out, sub->get_display_name(true),
                             summary.empty() ? sub->get_description() : std::string(summary), get_column_width());
    return out.str();
  }
};

}  // namespace

std::string_view command_summary(std::string_view command) {
  for (const auto& [name, summary] : kSummaries)
    if (name == command) return summary;
  return {};
}

void list_commands_in_one_line(CLI::App& app) {
  for (CLI::App* command : app.get_subcommands({})) command->group("Commands");  // CLI11's heading: "Subcommands"
  app.formatter(std::make_shared<OneLineCommandFormatter>());
}

}  // namespace vsgl::cli
