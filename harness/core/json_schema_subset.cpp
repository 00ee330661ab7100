#include "harness/core/json_schema_subset.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

namespace vsgl {
namespace {

using json = nlohmann::json;

const std::set<std::string> kKnownKeywords = {
    "$schema", "$id", "$defs", "$ref", "title", "description", "type", "properties", "required",
    "additionalProperties", "items", "minItems", "enum", "const", "minimum", "exclusiveMinimum"};

bool has_type(const json& v, const std::string& type) {
  if (type == "object") return v.is_object();
  if (type == "array") return v.is_array();
  if (type == "string") return v.is_string();
  if (type == "boolean") return v.is_boolean();
  if (type == "null") return v.is_null();
  if (type == "integer") return v.is_number_integer() || (v.is_number_float() && std::floor(v.get<double>()) == v.get<double>());
  if (type == "number") return v.is_number();
  throw std::invalid_argument("schema uses an unknown type '" + type + "'");
}

class Validator {
 public:
  explicit Validator(const json& root) : root_(root) {}

  void check(const json& v, const json& schema, const std::string& where) {
    if (schema.is_boolean()) {
      if (!schema.get<bool>()) fail(where, "not allowed here");
      return;
    }
    if (!schema.is_object()) throw std::invalid_argument("schema at " + where + " is neither an object nor a boolean");
    for (const auto& [key, _] : schema.items())
      if (!kKnownKeywords.count(key)) throw std::invalid_argument("schema keyword '" + key + "' is not supported");
    if (schema.contains("$ref")) {
      const std::string ref = schema["$ref"].get<std::string>();
      const std::string prefix = "#/$defs/";
      if (ref.rfind(prefix, 0) != 0 || !root_.contains("$defs") || !root_["$defs"].contains(ref.substr(prefix.size())))
        throw std::invalid_argument("schema $ref '" + ref + "' does not name an entry of $defs");
      check(v, root_["$defs"][ref.substr(prefix.size())], where);
    }
    if (schema.contains("type")) {
      const json& t = schema["type"];
      bool ok = false;
      std::string names;
      for (const auto& name : t.is_array() ? t : json::array({t})) {
        ok = ok || has_type(v, name.get<std::string>());
        names += (names.empty() ? "" : " or ") + name.get<std::string>();
      }
      if (!ok) {
        fail(where, "is " + std::string(v.type_name()) + ", expected " + names);
        return;
      }
    }
    if (schema.contains("enum")) {
      bool found = false;
      for (const auto& e : schema["enum"]) found = found || e == v;
      if (!found) fail(where, "value " + v.dump() + " is not one of " + schema["enum"].dump());
    }
    if (schema.contains("const") && schema["const"] != v) fail(where, "must be " + schema["const"].dump());
    if (v.is_number()) {
      const double x = v.get<double>();
      if (!std::isfinite(x)) fail(where, "is not a finite number");
      if (schema.contains("minimum") && x < schema["minimum"].get<double>())
        fail(where, "is below the minimum " + schema["minimum"].dump());
      if (schema.contains("exclusiveMinimum") && x <= schema["exclusiveMinimum"].get<double>())
        fail(where, "must be greater than " + schema["exclusiveMinimum"].dump());
    }
    if (v.is_object()) {
      if (schema.contains("required"))
        for (const auto& r : schema["required"])
          if (!v.contains(r.get<std::string>())) fail(where, "lacks the required member \"" + r.get<std::string>() + "\"");
      const json* props = schema.contains("properties") ? &schema["properties"] : nullptr;
      for (const auto& [key, member] : v.items()) {
        const std::string at = where + "/" + key;
        if (props != nullptr && props->contains(key)) check(member, (*props)[key], at);
        else if (schema.contains("additionalProperties")) check(member, schema["additionalProperties"], at);
      }
    }
    if (v.is_array()) {
      if (schema.contains("minItems") && v.size() < schema["minItems"].get<std::size_t>())
        fail(where, "has " + std::to_string(v.size()) + " items, fewer than " + schema["minItems"].dump());
      if (schema.contains("items"))
        for (std::size_t i = 0; i < v.size(); ++i) check(v[i], schema["items"], where + "/" + std::to_string(i));
    }
  }

  std::vector<std::string> errors;

 private:
  void fail(const std::string& where, const std::string& what) { errors.push_back((where.empty() ? "/" : where) + ": " + what); }
  const json& root_;
};

void walk_finite(const nlohmann::ordered_json& v, const std::string& where) {
  if (v.is_number_float() && !std::isfinite(v.get<double>()))
    throw std::invalid_argument("non-finite number at " + (where.empty() ? std::string("/") : where) +
                                ": a statistic that cannot be computed is an error, not a value");
  if (v.is_object())
    for (const auto& [key, member] : v.items()) walk_finite(member, where + "/" + key);
  if (v.is_array())
    for (std::size_t i = 0; i < v.size(); ++i) walk_finite(v[i], where + "/" + std::to_string(i));
}

}  // namespace

std::vector<std::string> validate_against_schema(const nlohmann::json& doc, const nlohmann::json& schema) {
  Validator v(schema);
  v.check(doc, schema, "");
  return v.errors;
}

void require_finite_numbers(const nlohmann::ordered_json& doc) { walk_finite(doc, ""); }

}  // namespace vsgl
