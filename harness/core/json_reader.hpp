#pragma once
// Reading JSON that came from outside (capture sidecars, table, sweep and quality documents,
// Google Benchmark runs, the paper's tables, schemas): one way to read and parse a file, and typed
// access where every failure names the file and the place in the document, so a bad input is an
// InputError that says what is wrong and where. The one reader of every document: its models
// (formats/) use it as it is, with no reader of their own.
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace vsgl {

// Reads and parses a whole file, keeping the order of its keys. `what` names it in messages ("the capture sidecar", "the table
// schema"); `hint` is appended to a read failure (" (use --paper FILE)"). Throws InputError.
nlohmann::ordered_json read_json_file(const std::filesystem::path& path, const std::string& what, const std::string& hint = "");

// Parses text already read (an embedded file, core/embedded_files.hpp); `name` says where it came from.
nlohmann::ordered_json parse_json_text(std::string_view text, const std::string& name, const std::string& what);

// How a place in a document is written in messages: dotted keys (`key "camera.position[2]"`,
// the sidecar's) or JSON pointers (`/generators/fis_tok15/total`, the runs').
enum class JsonPathStyle { kDottedKey, kPointer };

// Every document is an nlohmann::ordered_json (the one flavour: a file's keys keep their order).
class JsonReader {
 public:
  using json = nlohmann::ordered_json;
  JsonReader(std::string where, JsonPathStyle style) : where_(std::move(where)), style_(style) {}

  const std::string& where() const { return where_; }
  std::string child(const std::string& parent, std::string_view key) const;
  std::string element(const std::string& parent, std::size_t index) const;

  // "<where>: <place> <problem>", as InputError.
  [[noreturn]] void fail(const std::string& path, const std::string& problem) const;
  [[noreturn]] void wrong_type(const json& value, const std::string& path, const std::string& expected) const;

  // Each operation exists for a value at `path` and for the member `key` of an object at `parent`
  // (the member's path is child(parent, key)).
  const json& member(const json& object, const std::string& parent, std::string_view key) const;
  const json& object(const json& object, const std::string& parent, std::string_view key) const;
  std::string string(const json& object, const std::string& parent, std::string_view key) const;
  bool boolean(const json& object, const std::string& parent, std::string_view key) const;
  // A non-negative integer. A parsed file holds one as unsigned, a document built in memory may
  // hold it as signed: both are read.
  uint64_t uint64(const json& value, const std::string& path) const;
  uint64_t uint64(const json& object, const std::string& parent, std::string_view key) const;
  uint32_t uint32(const json& object, const std::string& parent, std::string_view key) const;
  // A finite number; `number32` also within float32 range.
  double number(const json& value, const std::string& path) const;
  double number(const json& object, const std::string& parent, std::string_view key) const;
  float number32(const json& value, const std::string& path) const;
  // A finite number >= 0 (an axis value, a growth x).
  double non_negative(const json& value, const std::string& path) const;
  // A time (ms, s): a finite number > 0 (DESIGN.md §9: every timing is positive by construction).
  double time(const json& value, const std::string& path) const;
  double time(const json& object, const std::string& parent, std::string_view key) const;
  // A non-empty array of times.
  std::vector<double> times(const json& object, const std::string& parent, std::string_view key) const;
  // An array of finite numbers, of any length.
  std::vector<double> numbers(const json& object, const std::string& parent, std::string_view key) const;
  // An object whose every value is a string, its pairs in the document's order.
  std::vector<std::pair<std::string, std::string>> string_map(const json& value, const std::string& path) const;

  // Optional members: absent (or null) is none; a present one must be of the type.
  std::optional<std::string> optional_string(const json& object, const std::string& parent, std::string_view key) const;
  std::optional<double> optional_number(const json& object, const std::string& parent, std::string_view key) const;
  std::optional<uint64_t> optional_uint64(const json& object, const std::string& parent, std::string_view key) const;
  // nullptr when absent or null.
  const json* optional_object(const json& object, const std::string& parent, std::string_view key) const;
  // A boolean that may be absent (then `fallback`).
  bool flag(const json& object, const std::string& parent, std::string_view key, bool fallback) const;

  // Refuses a key of `object` (at `parent`) that is not one of `known`, naming it and the known
  // ones: a misspelt key in a hand-written file is an error, never silently ignored.
  void only_keys(const json& object, const std::string& parent, std::initializer_list<std::string_view> known) const;
  // An array of any length; `nonempty_array` refuses an empty one; the last, exactly `count` numbers.
  const json& array(const json& object, const std::string& parent, std::string_view key) const;
  const json& nonempty_array(const json& object, const std::string& parent, std::string_view key) const;
  const json& array(const json& object, const std::string& parent, std::string_view key, std::size_t count) const;

 private:
  std::string place(const std::string& path) const;
  std::string where_;
  JsonPathStyle style_;
};

}  // namespace vsgl
