#include "harness/formats/devices_model.hpp"

#include <cstdint>
#include <string_view>

#include <nlohmann/json.hpp>

#include "harness/core/path_text.hpp"
#include "harness/core/embedded_files.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/core/json_schema_subset.hpp"

namespace vsgl {
namespace {

using json = nlohmann::json;

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

nlohmann::json to_json(const DeviceRecord& d) {
  json out{{"index", d.index},
           {"name", d.name},
           {"type", d.type},
           {"vendor_id", d.vendor_id},
           {"device_id", d.device_id},
           {"api_version", d.api_version},
           {"driver_version", d.driver_version},
           {"driver_name", d.driver_name},
           {"driver_info", d.driver_info},
           {"queue_family", d.queue_family},
           {"graphics", d.graphics},
           {"timestamps", d.timestamps},
           {"timestamp_valid_bits", d.timestamp_valid_bits},
           {"timestamp_period_ns", d.timestamp_period_ns},
           {"pipeline_statistics", d.pipeline_statistics},
           {"subgroup_size", d.subgroup_size},
           {"max_compute_shared_memory", d.max_compute_shared_memory},
           {"device_local_bytes", d.device_local_bytes},
           {"usable", d.usable},
           {"unusable_reason", d.unusable_reason}};
  if (d.limits) out["limits"] = to_json(*d.limits);
  return out;
}

nlohmann::json to_json(const DeviceSupport& s) {
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

nlohmann::json to_json(const DevicesDocument& doc) {
  json devices = json::array();
  for (const DeviceEntry& e : doc.devices) {
    json d = to_json(e.device);
    if (e.support) d["support"] = to_json(*e.support);
    devices.push_back(std::move(d));
  }
  return json{{"default", doc.default_index}, {"devices", devices}};
}

DeviceRecord device_from_json(const nlohmann::json& d, const std::string& where, const std::string& p) {
  const JsonReader r(where, JsonPathStyle::kPointer);
  if (!d.is_object()) r.wrong_type(d, p, "an object");
  // clang-format off
  r.only_keys(d, p,
              {"index", "name", "type", "vendor_id", "device_id", "api_version", "driver_version", "driver_name",
               "driver_info", "queue_family", "graphics", "timestamps", "timestamp_valid_bits",
               "timestamp_period_ns", "pipeline_statistics", "subgroup_size", "max_compute_shared_memory",
               "device_local_bytes", "limits", "usable", "unusable_reason"});
  // clang-format on
  DeviceRecord out;
  out.index = r.uint32(d, p, "index");
  out.name = r.string(d, p, "name");
  out.type = r.string(d, p, "type");
  out.vendor_id = r.uint32(d, p, "vendor_id");
  out.device_id = r.uint32(d, p, "device_id");
  out.api_version = r.string(d, p, "api_version");
  out.driver_version = r.string(d, p, "driver_version");
  out.driver_name = r.string(d, p, "driver_name");
  out.driver_info = r.string(d, p, "driver_info");
  out.queue_family = index_or_none(r, d, p, "queue_family");
  out.graphics = r.boolean(d, p, "graphics");
  out.timestamps = r.boolean(d, p, "timestamps");
  out.timestamp_valid_bits = r.uint32(d, p, "timestamp_valid_bits");
  out.timestamp_period_ns = r.number(d, p, "timestamp_period_ns");
  out.pipeline_statistics = r.boolean(d, p, "pipeline_statistics");
  out.subgroup_size = r.uint32(d, p, "subgroup_size");
  out.max_compute_shared_memory = r.uint32(d, p, "max_compute_shared_memory");
  out.device_local_bytes = r.uint64(d, p, "device_local_bytes");
  if (d.contains("limits")) out.limits = device_limits_from_json(r, r.object(d, p, "limits"), r.child(p, "limits"));
  out.usable = r.boolean(d, p, "usable");
  out.unusable_reason = r.string(d, p, "unusable_reason");
  return out;
}

DeviceSupport support_from_json(const nlohmann::json& s, const std::string& where, const std::string& p) {
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

DevicesDocument devices_from_json(const nlohmann::json& doc, const std::string& where) {
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
      e.device = device_from_json(rest, where, p);
    } else {
      e.device = device_from_json(d, where, p);
    }
    out.devices.push_back(std::move(e));
  }
  return out;
}

DevicesDocument read_devices_file(const std::filesystem::path& path) {
  return devices_from_json(json(read_json_file(path, "the devices document")), path_text(path));
}

std::string devices_file_text(const DevicesDocument& doc) {
  const json out = to_json(doc);
  require_conforming(nlohmann::ordered_json(out), json(embedded_json(kDevicesSchemaFile, "the devices schema")),
                     "the devices document", embedded_file_label(kDevicesSchemaFile));
  return out.dump(2) + "\n";
}

}  // namespace vsgl
