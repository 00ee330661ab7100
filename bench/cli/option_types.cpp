#include "bench/cli/option_types.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "harness/core/error.hpp"
#include "harness/core/platform_path.hpp"

namespace vsgl::cli {

std::string OptionNames::operator()(std::string_view name) const {
  std::string out(name);
  if (!gbench) return "--" + out;
  for (char& c : out)
    if (c == '-') c = '_';
  return "--vsgl_" + out;
}

namespace {

bool read_u32(std::string_view text, uint32_t& v) {
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  return !text.empty() && ec == std::errc() && ptr == text.data() + text.size();
}

}  // namespace

CLI::Validator at_least(uint32_t min) {
  return CLI::Validator(
      [min](std::string& text) -> std::string {
        uint32_t v = 0;
        if (!read_u32(text, v)) return "takes a whole number >= " + std::to_string(min) + ", not '" + text + "'";
        if (v < min) return "must be at least " + std::to_string(min) + ", not " + text;
        return {};
      },
      "N>=" + std::to_string(min));
}

CLI::Validator positive_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::size_t used = 0;
        double d = 0;
        try {
          d = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (text.empty() || used != text.size() || !std::isfinite(d)) return "takes a number, not '" + text + "'";
        if (!(d > 0)) return "must be positive, not " + text;
        return {};
      },
      "X>0");
}

CLI::Validator size_text() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const auto x = text.find('x');
        uint32_t w = 0, h = 0;
        if (x == std::string::npos || !read_u32(std::string_view(text).substr(0, x), w) ||
            !read_u32(std::string_view(text).substr(x + 1), h))
          return "takes WIDTHxHEIGHT (e.g. 1920x1088), not '" + text + "'";
        if (w == 0 || h == 0) return "must be at least 1x1, not " + text;
        return {};
      },
      "");  // the type name says WxH
}

CLI::Validator input_file(std::string what) {
  return CLI::Validator(
      [what](std::string& text) -> std::string {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(path_from_utf8(text), ec))
          throw InputError(what + " " + text + ": no such file");
        return {};
      },
      "FILE");
}

CLI::Validator usage_checked(std::function<void(const std::string&)> parse, std::string description) {
  return CLI::Validator(
      [parse](std::string& text) -> std::string {
        try {
          parse(text);
        } catch (const UsageError& e) {
          std::string why = e.what();
          if (why.rfind("--", 0) == 0 && why.find(' ') != std::string::npos) why = why.substr(why.find(' ') + 1);
          return why;
        }
        return {};
      },
      std::move(description));
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

CLI::Validator list_of(const CLI::Validator& item) {
  return CLI::Validator(
      [item](std::string& text) -> std::string {
        const auto items = split_list(text);
        if (items.empty()) return "needs at least one item";
        for (std::string i : items)
          if (std::string why = item(i); !why.empty()) return "item '" + i + "' " + why;
        return {};
      },
      "");
}

CLI::Validator one_of(std::vector<std::string> names) {
  std::string joined;
  for (std::size_t i = 0; i < names.size(); ++i)
    joined += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return CLI::Validator(
      [names, joined](std::string& text) -> std::string {
        for (const auto& n : names)
          if (text == n) return {};
        return "takes " + joined + ", not '" + text + "'";
      },
      joined);
}

std::pair<uint32_t, uint32_t> parse_size(const std::string& text) {
  const auto x = text.find('x');
  uint32_t w = 0, h = 0;
  read_u32(std::string_view(text).substr(0, x), w);
  read_u32(std::string_view(text).substr(x + 1), h);
  return {w, h};
}

CLI::Option* add_size_option(CLI::App& app, const std::string& name, std::pair<uint32_t, uint32_t>& target,
                             const std::string& description) {
  return app
      .add_option_function<std::string>(name, [&target](const std::string& text) { target = parse_size(text); },
                                        description)
      ->check(size_text())
      ->type_name("WxH")
      ->default_str(std::to_string(target.first) + "x" + std::to_string(target.second));
}

CLI::Option* add_list_option(CLI::App& app, const std::string& name, std::vector<std::string>& target,
                             const std::string& description, const CLI::Validator& item) {
  std::string shown;
  for (const auto& t : target) shown += (shown.empty() ? "" : ",") + t;
  auto* o = app.add_option_function<std::string>(name, [&target](const std::string& text) { target = split_list(text); },
                                                 description)
                ->check(list_of(item))
                ->type_name("A[,B...]");
  if (!shown.empty()) o->default_str(shown);
  return o;
}

CLI::Option* add_assets_option(CLI::App& app, std::vector<std::string>& target, const OptionNames& names) {
  return add_list_option(app, names("assets"), target,
                         "look for the scene presets' models here, before VSGL_ASSETS and assets/ in the current "
                         "directory (repeatable)",
                         CLI::Validator([](std::string&) { return std::string(); }, "DIR"));
}

}  // namespace vsgl::cli
