#pragma once
// Reading JSON that came from outside (capture sidecars, table and Google Benchmark runs, the
// paper's tables, schemas): one way to read and parse a file, and typed access where every
// failure names the file and the place in the document, so a bad input is an InputError that
// says what is wrong and where.
#include <cstdint>
#include <initializer_list>
#include <filesystem>
#include <string>
#include <string_view>

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

// For nlohmann::json and nlohmann::ordered_json alike (explicitly instantiated for both), so a
// document is read in the type it was parsed into, never copied into the other.
template <typename Json>
class BasicJsonReader {
 public:
  using json = Json;
  BasicJsonReader(std::string where, JsonPathStyle style) : where_(std::move(where)), style_(style) {}

  const std::string& where() const { return where_; }
  std::string child(const std::string& parent, std::string_view key) const;
  std::string element(const std::string& parent, std::size_t index) const;

  // "<where>: <place> <problem>", as InputError.
  [[noreturn]] void fail(const std::string& path, const std::string& problem) const;
  [[noreturn]] void wrong_type(const json& value, const std::string& path, const std::string& expected) const;

  const json& member(const json& object, const std::string& parent, std::string_view key) const;
  const json& object(const json& object, const std::string& parent, std::string_view key) const;
  std::string string(const json& object, const std::string& parent, std::string_view key) const;
  bool boolean(const json& object, const std::string& parent, std::string_view key) const;
  uint32_t uint32(const json& object, const std::string& parent, std::string_view key) const;
  // A finite number; `number32` also within float32 range.
  double number(const json& value, const std::string& path) const;
  double number(const json& object, const std::string& parent, std::string_view key) const;
  float number32(const json& value, const std::string& path) const;
  // Refuses a key of `object` (at `parent`) that is not one of `known`, naming it and the known
  // ones: a misspelt key in a hand-written file is an error, never silently ignored.
  void only_keys(const json& object, const std::string& parent, std::initializer_list<std::string_view> known) const;
  // An array of exactly `count` elements.
  const json& array(const json& object, const std::string& parent, std::string_view key, std::size_t count) const;

 private:
  std::string place(const std::string& path) const;
  std::string where_;
  JsonPathStyle style_;
};

extern template class BasicJsonReader<nlohmann::json>;
extern template class BasicJsonReader<nlohmann::ordered_json>;
using JsonReader = BasicJsonReader<nlohmann::json>;
using OrderedJsonReader = BasicJsonReader<nlohmann::ordered_json>;

}  // namespace vsgl
