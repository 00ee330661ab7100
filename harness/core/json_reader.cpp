#include "harness/core/json_reader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "harness/core/error.hpp"
#include "harness/core/path_text.hpp"
#include "harness/core/printable_text.hpp"
#include "harness/core/text_file.hpp"
#include "harness/core/text_format.hpp"

namespace vsgl {

nlohmann::ordered_json read_json_file(const std::filesystem::path& path, const std::string& what, const std::string& hint) {
  return parse_json_text(read_text_file(path, what, hint), path_text(path), what);
}

nlohmann::ordered_json parse_json_text(std::string_view text, const std::string& name, const std::string& what) {
  try {
    return nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::ordered_json::exception& e) {
    throw InputError(name + ": " + what + " is not valid JSON (truncated or corrupt?): " + printable_text(e.what()));
  }
}

std::string JsonReader::child(const std::string& parent, std::string_view key) const {
  if (style_ == JsonPathStyle::kPointer) return parent + "/" + std::string(key);
  return parent.empty() ? std::string(key) : parent + "." + std::string(key);
}

std::string JsonReader::element(const std::string& parent, std::size_t index) const {
  if (style_ == JsonPathStyle::kPointer) return parent + "/" + std::to_string(index);
  return parent + "[" + std::to_string(index) + "]";
}

std::string JsonReader::place(const std::string& path) const {
  // Paths are made of the file's keys: escaped, as every text from a file in a message.
  if (style_ == JsonPathStyle::kPointer) return path.empty() ? "" : printable_text(path) + ": ";
  return path.empty() ? "" : "key " + quoted_text(path) + " ";
}

void JsonReader::fail(const std::string& path, const std::string& problem) const {
  throw InputError(where_ + ": " + place(path) + problem);
}

void JsonReader::wrong_type(const json& value, const std::string& path, const std::string& expected) const {
  fail(path, std::string("has type ") + value.type_name() + ", expected " + expected);
}

const nlohmann::ordered_json& JsonReader::member(const json& object, const std::string& parent,
                                                 std::string_view key) const {
  if (!object.is_object()) fail(parent, "is not an object");
  const auto it = object.find(std::string(key));
  if (it == object.end()) fail(child(parent, key), style_ == JsonPathStyle::kPointer ? "missing field" : "is missing");
  return *it;
}

const nlohmann::ordered_json& JsonReader::object(const json& object, const std::string& parent,
                                                 std::string_view key) const {
  const json& value = member(object, parent, key);
  if (!value.is_object()) wrong_type(value, child(parent, key), "an object");
  return value;
}

std::string JsonReader::string(const json& object, const std::string& parent, std::string_view key) const {
  const json& value = member(object, parent, key);
  if (!value.is_string()) wrong_type(value, child(parent, key), "a string");
  return value.get<std::string>();
}

bool JsonReader::boolean(const json& object, const std::string& parent, std::string_view key) const {
  const json& value = member(object, parent, key);
  if (!value.is_boolean()) wrong_type(value, child(parent, key), "a boolean");
  return value.get<bool>();
}

uint64_t JsonReader::uint64(const json& value, const std::string& path) const {
  // nlohmann parses every non-negative integer literal as number_unsigned; one set in memory from
  // a signed value is number_integer.
  if (!value.is_number_integer() || (!value.is_number_unsigned() && value.get<int64_t>() < 0))
    wrong_type(value, path, "a non-negative integer");
  return value.get<uint64_t>();
}

uint64_t JsonReader::uint64(const json& object, const std::string& parent, std::string_view key) const {
  return uint64(member(object, parent, key), child(parent, key));
}

uint32_t JsonReader::uint32(const json& object, const std::string& parent, std::string_view key) const {
  const json& value = member(object, parent, key);
  if (!value.is_number_integer() || (!value.is_number_unsigned() && value.get<int64_t>() < 0) ||
      value.get<uint64_t>() > std::numeric_limits<uint32_t>::max())
    wrong_type(value, child(parent, key), "an unsigned 32-bit integer");
  return static_cast<uint32_t>(value.get<uint64_t>());
}

double JsonReader::number(const json& value, const std::string& path) const {
  if (!value.is_number()) wrong_type(value, path, "a number");
  const double number = value.get<double>();
  if (!std::isfinite(number)) fail(path, "is not a finite number");
  return number;
}

double JsonReader::number(const json& object, const std::string& parent, std::string_view key) const {
  return number(member(object, parent, key), child(parent, key));
}

float JsonReader::number32(const json& value, const std::string& path) const {
  const double v = number(value, path);
  if (std::abs(v) > static_cast<double>(std::numeric_limits<float>::max())) {
    fail(path, "(" + number_text(v) + ") is out of float32 range");
  }
  return static_cast<float>(v);
}

double JsonReader::non_negative(const json& value, const std::string& path) const {
  const double x = number(value, path);
  if (x < 0) fail(path, "is negative (" + printable_text(value.dump()) + ")");
  return x;
}

double JsonReader::time(const json& value, const std::string& path) const {
  const double t = number(value, path);
  if (!(t > 0)) fail(path, "is not a positive time (" + printable_text(value.dump()) + ")");
  return t;
}

double JsonReader::time(const json& object, const std::string& parent, std::string_view key) const {
  return time(member(object, parent, key), child(parent, key));
}

std::vector<double> JsonReader::times(const json& object, const std::string& parent, std::string_view key) const {
  const std::string path = child(parent, key);
  const json& a = member(object, parent, key);
  if (!a.is_array() || a.empty()) fail(path, "is not a non-empty array");
  std::vector<double> out;
  for (std::size_t i = 0; i < a.size(); ++i) out.push_back(time(a[i], element(path, i)));
  return out;
}

std::vector<double> JsonReader::numbers(const json& object, const std::string& parent, std::string_view key) const {
  const std::string path = child(parent, key);
  const json& a = array(object, parent, key);
  std::vector<double> out;
  for (std::size_t i = 0; i < a.size(); ++i) out.push_back(number(a[i], element(path, i)));
  return out;
}

std::vector<std::pair<std::string, std::string>> JsonReader::string_map(const json& value,
                                                                        const std::string& path) const {
  if (!value.is_object()) wrong_type(value, path, "an object");
  std::vector<std::pair<std::string, std::string>> out;
  for (auto it = value.begin(); it != value.end(); ++it) {
    if (!it->is_string()) wrong_type(*it, child(path, it.key()), "a string");
    out.emplace_back(it.key(), it->template get<std::string>());
  }
  return out;
}

std::optional<std::string> JsonReader::optional_string(const json& object, const std::string& parent,
                                                       std::string_view key) const {
  const auto it = object.find(std::string(key));
  if (it == object.end() || it->is_null()) return std::nullopt;
  return string(object, parent, key);
}

std::optional<double> JsonReader::optional_number(const json& object, const std::string& parent,
                                                  std::string_view key) const {
  const auto it = object.find(std::string(key));
  if (it == object.end() || it->is_null()) return std::nullopt;
  return number(*it, child(parent, key));
}

std::optional<uint64_t> JsonReader::optional_uint64(const json& object, const std::string& parent,
                                                    std::string_view key) const {
  const auto it = object.find(std::string(key));
  if (it == object.end() || it->is_null()) return std::nullopt;
  return uint64(*it, child(parent, key));
}

const nlohmann::ordered_json* JsonReader::optional_object(const json& object, const std::string& parent,
                                                          std::string_view key) const {
  const auto it = object.find(std::string(key));
  if (it == object.end() || it->is_null()) return nullptr;
  return &this->object(object, parent, key);
}

bool JsonReader::flag(const json& object, const std::string& parent, std::string_view key, bool fallback) const {
  const auto it = object.find(std::string(key));
  if (it == object.end()) return fallback;
  return boolean(object, parent, key);
}

const nlohmann::ordered_json& JsonReader::array(const json& object, const std::string& parent,
                                                std::string_view key) const {
  const json& value = member(object, parent, key);
  if (!value.is_array()) wrong_type(value, child(parent, key), "an array");
  return value;
}

const nlohmann::ordered_json& JsonReader::nonempty_array(const json& object, const std::string& parent,
                                                         std::string_view key) const {
  const json& value = array(object, parent, key);
  if (value.empty()) fail(child(parent, key), "is empty");
  return value;
}

const nlohmann::ordered_json& JsonReader::array(const json& object, const std::string& parent, std::string_view key,
                                                std::size_t count) const {
  const std::string path = child(parent, key);
  const json& value = member(object, parent, key);
  const std::string expected = "an array of " + std::to_string(count) + " numbers";
  if (!value.is_array()) wrong_type(value, path, expected);
  if (value.size() != count)
    fail(path, "has " + std::to_string(value.size()) + " elements, expected " + expected);
  return value;
}

void JsonReader::only_keys(const json& object, const std::string& parent,
                           std::initializer_list<std::string_view> known) const {
  for (auto it = object.begin(); it != object.end(); ++it) {
    if (std::find(known.begin(), known.end(), std::string_view(it.key())) != known.end()) continue;
    std::string names;
    for (std::string_view k : known) names += (names.empty() ? "" : ", ") + std::string(k);
    fail(child(parent, printable_text(it.key(), 80)), "is not a known key (known: " + names + ")");
  }
}

}  // namespace vsgl
