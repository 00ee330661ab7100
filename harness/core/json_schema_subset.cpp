#include "harness/core/json_schema_subset.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace vsgl {
namespace {

using json = nlohmann::ordered_json;

const std::set<std::string> kKnownKeywords = {
    "$schema", "$id", "$defs", "$ref", "title", "description", "type", "properties", "required",
    "additionalProperties", "items", "minItems", "enum", "const", "minimum", "exclusiveMinimum"};
const std::set<std::string> kTypeNames = {"object", "array", "string", "boolean", "null", "integer", "number"};
const std::string kRefPrefix = "#/$defs/";

// Keywords of drafts 7 and 2020-12 whose values hold subschemas, outside the subset: walked so
// that a problem under them is reported too, not only the keyword itself.
const std::set<std::string> kSchemaMapKeywords = {"definitions", "patternProperties", "dependentSchemas",
                                                  "dependencies"};
const std::set<std::string> kSchemaKeywords = {
    "additionalItems",       "contains",     "not", "if", "then", "else", "propertyNames", "unevaluatedItems",
    "unevaluatedProperties", "contentSchema"};
const std::set<std::string> kSchemaListKeywords = {"allOf", "anyOf", "oneOf", "prefixItems"};

// JSON pointer escaping (RFC 6901) of one reference token.
std::string pointer_token(const std::string& key) {
  std::string out;
  for (const char c : key) out += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
  return out;
}

class SchemaWalker {
 public:
  explicit SchemaWalker(const json& root) : root_(root) {}

  void walk(const json& s, const std::string& at, bool is_root) {
    if (s.is_boolean()) return;
    if (!s.is_object()) return problem(at, "is neither a schema object nor a boolean");
    for (const auto& [key, value] : s.items()) {
      const std::string here = at + "/" + pointer_token(key);
      if (!kKnownKeywords.count(key)) {
        problem(here, "keyword '" + key + "' is not supported by the validator");
        if (kSchemaKeywords.count(key)) walk(value, here, false);
        if (kSchemaMapKeywords.count(key) && value.is_object())
          for (const auto& [name, sub] : value.items())
            if (sub.is_object() || sub.is_boolean()) walk(sub, here + "/" + pointer_token(name), false);
        if (kSchemaListKeywords.count(key) && value.is_array())
          for (std::size_t i = 0; i < value.size(); ++i) walk(value[i], here + "/" + std::to_string(i), false);
        continue;
      }
      check_keyword(key, value, here, is_root);
    }
  }

  std::vector<std::string> problems;

 private:
  void check_keyword(const std::string& key, const json& value, const std::string& here, bool is_root) {
    if (key == "$schema" || key == "$id" || key == "title" || key == "description") {
      if (!value.is_string()) problem(here, "must be a string");
    } else if (key == "type") {
      const bool listed = value.is_array() && !value.empty();
      for (const auto& name : listed ? value : json::array({value}))
        if (!name.is_string() || !kTypeNames.count(name.get<std::string>()))
          problem(here, "names no JSON type: " + name.dump());
    } else if (key == "properties" || key == "$defs") {
      if (key == "$defs" && !is_root) problem(here, "$defs only at the root ($ref resolves against the root's)");
      if (!value.is_object()) return problem(here, "must be an object of schemas");
      for (const auto& [name, sub] : value.items()) walk(sub, here + "/" + pointer_token(name), false);
    } else if (key == "additionalProperties" || key == "items") {
      if (value.is_array()) return problem(here, "must be one schema (a list of schemas is not supported)");
      walk(value, here, false);
    } else if (key == "required") {
      if (!value.is_array()) return problem(here, "must be an array of member names");
      for (const auto& name : value)
        if (!name.is_string()) problem(here, "names a member with a non-string " + name.dump());
    } else if (key == "minItems") {
      if (!value.is_number_unsigned()) problem(here, "must be a non-negative integer");
    } else if (key == "minimum" || key == "exclusiveMinimum") {
      if (!value.is_number()) problem(here, "must be a number (draft 4's boolean form is not supported)");
    } else if (key == "enum") {
      if (!value.is_array()) problem(here, "must be an array");
    } else if (key == "$ref") {
      const bool resolves = value.is_string() && value.get<std::string>().rfind(kRefPrefix, 0) == 0 &&
                            root_.contains("$defs") && root_["$defs"].is_object() &&
                            root_["$defs"].contains(value.get<std::string>().substr(kRefPrefix.size()));
      if (!resolves) problem(here, value.dump() + " does not name an entry of the root's $defs");
    }
    // "const": any value.
  }

  void problem(const std::string& at, const std::string& what) {
    problems.push_back((at.empty() ? "/" : at) + ": " + what);
  }
  const json& root_;
};

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
    if (schema.contains("$ref"))  // it resolves: schema_subset_problems checked it before
      check(v, root_["$defs"][schema["$ref"].get<std::string>().substr(kRefPrefix.size())], where);
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

// One problem per indented line, for an error message.
std::string problem_lines(const std::vector<std::string>& problems) {
  std::string all;
  for (const auto& p : problems) all += "\n  " + p;
  return all;
}

}  // namespace

std::vector<std::string> schema_subset_problems(const nlohmann::ordered_json& schema) {
  SchemaWalker w(schema);
  w.walk(schema, "", true);
  return w.problems;
}

std::vector<std::string> validate_against_schema(const nlohmann::ordered_json& doc,
                                                 const nlohmann::ordered_json& schema) {
  if (const auto problems = schema_subset_problems(schema); !problems.empty())
    throw std::invalid_argument("the schema asks for what the validator cannot check:" + problem_lines(problems));
  Validator v(schema);
  v.check(doc, schema, "");
  return v.errors;
}

void require_conforming(const nlohmann::ordered_json& doc, const nlohmann::ordered_json& schema,
                        const std::string& what, const std::string& schema_name) {
  const auto problems = validate_against_schema(doc, schema);
  if (!problems.empty())
    throw std::logic_error(what + " does not conform to " + schema_name + ":" + problem_lines(problems));
}

void require_finite_numbers(const nlohmann::ordered_json& doc) { walk_finite(doc, ""); }

}  // namespace vsgl
