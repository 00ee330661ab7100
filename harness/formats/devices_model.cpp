#include "harness/formats/devices_model.hpp"

#include <cstdint>
#include <string_view>

#include <nlohmann/json.hpp>

#include "harness/core/path_text.hpp"
#include "harness/core/embedded_files.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/core/json_schema_subset.hpp"
#include "harness/core/sorted_json.hpp"

namespace vsgl {
namespace {

using json = nlohmann::ordered_json;

// ---- writing ----

json verdict_json(const SupportVerdict& v) { return json{{"runs", v.runs}, {"reason", v.reason}}; }

// ---- reading ----

// An index that may be -1 for none.
int64_t index_or_none(const JsonReader& r, const json& object, const std::string& parent, std::string_view key) {
  const json& v = r.member(object, parent, key);
  const bool fits =
      v.is_number_unsigned() ? v.get<uint64_t>() <= UINT32_MAX : v.is_number_integer() && v.get<int64_t>() >= -1;
  if (!fits) r.wrong_type(v, r.child(parent, key), "an index or -1");
  return v.get<int64_t>();
}

std::optional<std::string> optional_string(const JsonReader& r, const json& object, const std::string& parent,
                                           std::string_view key) {
  if (!object.contains(std::string(key))) return std::nullopt;
  return r.string(object, parent, key);
}

SupportVerdict read_verdict(const JsonReader& r, const json& v, const std::string& p) {
  return {r.boolean(v, p, "runs"), r.string(v, p, "reason")};
}

}  // namespace

nlohmann::ordered_json to_json(const DeviceSupport& s) {
  json generators = json::object();
  for (const auto& [name, g] : s.generators) {
    json j = verdict_json(g.verdict);
    if (g.pyramid) j["pyramid"] = *g.pyramid;
    if (g.pyramid_fallback_reason) j["pyramid_fallback_reason"] = *g.pyramid_fallback_reason;
    if (g.mipmapping) j["mipmapping"] = *g.mipmapping;
    if (g.mipmapping_fallback_reason) j["mipmapping_fallback_reason"] = *g.mipmapping_fallback_reason;
    generators[name] = j;
  }
  json mipmapping = json::object();
  for (const auto& [strategy, v] : s.mipmapping) mipmapping[strategy] = verdict_json(v);
  return json{{"generators", generators}, {"mipmapping", mipmapping}};
}

nlohmann::ordered_json to_json(const DevicesDocument& doc) {
  json devices = json::array();
  for (const DeviceEntry& e : doc.devices) {
    json d = to_json(e.device);
    if (e.support) d["support"] = to_json(*e.support);
    devices.push_back(std::move(d));
  }
  return sorted_keys(json{{"default", doc.default_index}, {"devices", devices}});
}

DeviceSupport support_from_json(const nlohmann::ordered_json& s, const std::string& where, const std::string& p) {
  const JsonReader r(where, JsonPathStyle::kPointer);
  if (!s.is_object()) r.wrong_type(s, p, "an object");
  r.only_keys(s, p, {"generators", "mipmapping"});
  DeviceSupport out;
  const std::string gp = r.child(p, "generators");
  for (const auto& [name, g] : r.object(s, p, "generators").items()) {
    const std::string np = r.child(gp, name);
    if (!g.is_object()) r.wrong_type(g, np, "an object");
    r.only_keys(g, np,
                {"runs", "reason", "pyramid", "pyramid_fallback_reason", "mipmapping", "mipmapping_fallback_reason"});
    out.generators[name] = {read_verdict(r, g, np), optional_string(r, g, np, "pyramid"),
                            optional_string(r, g, np, "pyramid_fallback_reason"),
                            optional_string(r, g, np, "mipmapping"),
                            optional_string(r, g, np, "mipmapping_fallback_reason")};
  }
  const std::string mp = r.child(p, "mipmapping");
  for (const auto& [strategy, v] : r.object(s, p, "mipmapping").items()) {
    const std::string sp = r.child(mp, strategy);
    if (!v.is_object()) r.wrong_type(v, sp, "an object");
    r.only_keys(v, sp, {"runs", "reason"});
    out.mipmapping[strategy] = read_verdict(r, v, sp);
  }
  return out;
}

DevicesDocument devices_from_json(const nlohmann::ordered_json& doc, const std::string& where) {
  const JsonReader r(where, JsonPathStyle::kPointer);
  if (!doc.is_object()) r.wrong_type(doc, "", "an object");
  r.only_keys(doc, "", {"default", "devices"});
  DevicesDocument out;
  out.default_index = index_or_none(r, doc, "", "default");
  const json& devices = r.member(doc, "", "devices");
  if (!devices.is_array()) r.wrong_type(devices, "/devices", "an array");
  for (std::size_t i = 0; i < devices.size(); ++i) {
    const std::string p = r.element("/devices", i);
    const json& d = devices[i];
    DeviceEntry e;
    if (d.is_object() && d.contains("support")) {
      e.support = support_from_json(d.at("support"), where, r.child(p, "support"));
      json rest = d;
      rest.erase("support");
      e.device = device_record_from_json(r, rest, p);
    } else {
      e.device = device_record_from_json(r, d, p);
    }
    out.devices.push_back(std::move(e));
  }
  return out;
}

DevicesDocument read_devices_file(const std::filesystem::path& path) {
  return devices_from_json(read_json_file(path, "the devices document"), path_text(path));
}

std::string devices_file_text(const DevicesDocument& doc) {
  const json out = to_json(doc);
  require_conforming(out, embedded_json(kDevicesSchemaFile, "the devices schema"), "the devices document",
                     embedded_file_label(kDevicesSchemaFile));
  return out.dump(2) + "\n";
}

}  // namespace vsgl
