#include "harness/formats/verify_model.hpp"

#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "harness/core/path_text.hpp"
#include "harness/core/embedded_files.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/core/json_schema_subset.hpp"
#include "harness/core/sorted_json.hpp"

namespace vsgl {
namespace {

using json = nlohmann::ordered_json;

const char* kind_name(VerifyCheckKind kind) { return kind == VerifyCheckKind::kMeasurement ? "measurement" : "check"; }

VerifyCheck read_check(const JsonReader& r, const json& c, const std::string& p) {
  if (!c.is_object()) r.wrong_type(c, p, "an object");
  r.only_keys(c, p, {"view", "generator", "check", "kind", "measured", "tolerance", "expected", "passed", "detail"});
  VerifyCheck out;
  out.view = r.string(c, p, "view");
  out.generator = r.string(c, p, "generator");
  out.check = r.string(c, p, "check");
  if (c.contains("kind")) {
    const std::string kind = r.string(c, p, "kind");
    if (kind == "check") out.kind = VerifyCheckKind::kCheck;
    else if (kind == "measurement") out.kind = VerifyCheckKind::kMeasurement;
    else r.fail(r.child(p, "kind"), "is neither \"check\" nor \"measurement\"");
  }
  // A non-finite error is written as null (nlohmann::ordered_json has no NaN): it reads back as NaN.
  const json& measured = r.member(c, p, "measured");
  out.measured =
      measured.is_null() ? std::numeric_limits<double>::quiet_NaN() : r.number(measured, r.child(p, "measured"));
  // A check has a tolerance, a measurement an expectation, never both.
  const char* needed = out.is_measurement() ? "expected" : "tolerance";
  const char* refused = out.is_measurement() ? "tolerance" : "expected";
  if (c.contains(refused))
    r.fail(r.child(p, refused),
           std::string("is not a field of a ") + kind_name(out.kind.value_or(VerifyCheckKind::kCheck)));
  (out.is_measurement() ? out.expected : out.tolerance) = r.number(c, p, needed);
  out.passed = r.boolean(c, p, "passed");
  out.detail = r.string(c, p, "detail");
  return out;
}

}  // namespace

nlohmann::ordered_json to_json(const VerifyCheck& c) {
  // A non-finite error is null in the file (JSON has no NaN), which the schema allows.
  const json measured = std::isfinite(c.measured) ? json(c.measured) : json(nullptr);
  json out{{"view", c.view},       {"generator", c.generator}, {"check", c.check},
           {"measured", measured}, {"passed", c.passed},       {"detail", c.detail}};
  if (c.kind) out["kind"] = kind_name(*c.kind);
  if (c.tolerance) out["tolerance"] = *c.tolerance;
  if (c.expected) out["expected"] = *c.expected;
  return sorted_keys(out);
}

nlohmann::ordered_json to_json(const VerifyDocument& doc) {
  json checks = json::array();
  for (const VerifyCheck& c : doc.checks) checks.push_back(to_json(c));
  return sorted_keys(
      json{{"capture", doc.capture}, {"scene", doc.scene}, {"device", to_json(doc.device)}, {"checks", checks}});
}

VerifyDocument verify_from_json(const nlohmann::ordered_json& doc, const std::string& where) {
  const JsonReader r(where, JsonPathStyle::kPointer);
  if (!doc.is_object()) r.wrong_type(doc, "", "an object");
  r.only_keys(doc, "", {"capture", "scene", "device", "checks"});
  VerifyDocument out;
  out.capture = r.string(doc, "", "capture");
  out.scene = r.string(doc, "", "scene");
  out.device = device_record_from_json(r, r.object(doc, "", "device"), "/device");
  const json& checks = r.member(doc, "", "checks");
  if (!checks.is_array()) r.wrong_type(checks, "/checks", "an array");
  for (std::size_t i = 0; i < checks.size(); ++i)
    out.checks.push_back(read_check(r, checks[i], r.element("/checks", i)));
  return out;
}

VerifyDocument read_verify_file(const std::filesystem::path& path) {
  return verify_from_json(read_json_file(path, "the verify document"), path_text(path));
}

std::string verify_file_text(const VerifyDocument& doc) {
  const json out = to_json(doc);
  require_conforming(out, embedded_json(kVerifySchemaFile, "the verify schema"), "the verify document",
                     embedded_file_label(kVerifySchemaFile));
  return out.dump(2) + "\n";
}

}  // namespace vsgl
