#pragma once
// Validators and option helpers of the front ends (CLI11): numbers with a lower bound, sizes
// "WxH", lists "a,b,c" checked item by item, and the naming of options (vsgl-bench's
// --camera-vsgls is vsgl-gbench's --vsgl_camera_vsgls, declared by the same code).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

namespace vsgl::cli {

// How a front end spells an option: "camera-vsgls" -> "--camera-vsgls" (vsgl-bench) or
// "--vsgl_camera_vsgls" (the Google Benchmark front ends, whose own flags are --benchmark_*).
struct OptionNames {
  bool gbench = false;
  std::string operator()(std::string_view name) const;
};

// A whole number >= min (N >= 1, R >= 2, ...).
CLI::Validator at_least(uint32_t min);
// A finite number > 0.
CLI::Validator positive_number();
// "WxH" with W, H >= 1.
CLI::Validator size_text();
// "a,b,c": every non-empty item passes `item` (and at least one item is given).
CLI::Validator list_of(const CLI::Validator& item);
// A file that must exist: a missing one is bad input (exit 3, like a file that fails to load), not a
// typo of the command line, so the check throws InputError instead of returning a message.
CLI::Validator input_file(std::string what);
// One of `names` (the message lists them).
CLI::Validator one_of(std::vector<std::string> names);

// A check by a parser of the harness that throws UsageError ("--fail-on takes ..."): its message,
// without the option name CLI11 puts in front anyway.
CLI::Validator usage_checked(std::function<void(const std::string&)> parse, std::string description);

// "a,b,c" -> {"a", "b", "c"} (empty items dropped).
std::vector<std::string> split_list(const std::string& text);
// "WxH" -> {W, H}; the text has passed size_text().
std::pair<uint32_t, uint32_t> parse_size(const std::string& text);

// --name WxH into `target` (its value shown as the default).
CLI::Option* add_size_option(CLI::App& app, const std::string& name, std::pair<uint32_t, uint32_t>& target,
                             const std::string& description);
// --name a,b,c into `target` (the last occurrence wins), each item checked by `item`.
CLI::Option* add_list_option(CLI::App& app, const std::string& name, std::vector<std::string>& target,
                             const std::string& description, const CLI::Validator& item);

// --assets DIR (repeatable): where the paper scenes' models are looked for first (DESIGN.md §3.4).
CLI::Option* add_assets_option(CLI::App& app, std::vector<std::string>& target, const OptionNames& names = {});

// --name V into an optional (unset when not given).
template <class T>
CLI::Option* add_optional(CLI::App& app, const std::string& name, std::optional<T>& target,
                          const std::string& description) {
  return app.add_option_function<T>(name, [&target](const T& v) { target = v; }, description);
}

}  // namespace vsgl::cli
