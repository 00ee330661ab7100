#include "harness/formats/devices_model.hpp"

#include <array>
#include <cstdint>
#include <iterator>
#include <limits>
#include <string_view>

#include <nlohmann/json.hpp>

#include "harness/core/embedded_files.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/core/json_schema_subset.hpp"

namespace vsgl {
namespace {

using json = nlohmann::json;

// The 32-bit limits, by their key in the file; the three others (two 3-vectors and the 64-bit
// allocation size) and the format features are written out below.
struct Limit32 {
  const char* key;
  uint32_t DeviceLimitsRecord::*field;
};
constexpr Limit32 kLimits32[] = {
    {"maxPerStageDescriptorStorageImages", &DeviceLimitsRecord::per_stage_storage_images},
    {"maxPerStageDescriptorSampledImages", &DeviceLimitsRecord::per_stage_sampled_images},
    {"maxPerStageDescriptorSamplers", &DeviceLimitsRecord::per_stage_samplers},
    {"maxPerStageDescriptorStorageBuffers", &DeviceLimitsRecord::per_stage_storage_buffers},
    {"maxPerStageDescriptorUniformBuffers", &DeviceLimitsRecord::per_stage_uniform_buffers},
    {"maxPerStageResources", &DeviceLimitsRecord::per_stage_resources},
    {"maxDescriptorSetStorageImages", &DeviceLimitsRecord::set_storage_images},
    {"maxDescriptorSetSampledImages", &DeviceLimitsRecord::set_sampled_images},
    {"maxDescriptorSetSamplers", &DeviceLimitsRecord::set_samplers},
    {"maxDescriptorSetStorageBuffers", &DeviceLimitsRecord::set_storage_buffers},
    {"maxDescriptorSetUniformBuffers", &DeviceLimitsRecord::set_uniform_buffers},
    {"maxBoundDescriptorSets", &DeviceLimitsRecord::bound_descriptor_sets},
    {"maxPushConstantsSize", &DeviceLimitsRecord::push_constants_size},
    {"maxComputeSharedMemorySize", &DeviceLimitsRecord::compute_shared_memory},
    {"maxComputeWorkGroupInvocations", &DeviceLimitsRecord::workgroup_invocations},
    {"maxImageDimension2D", &DeviceLimitsRecord::image_dimension_2d},
    {"maxImageArrayLayers", &DeviceLimitsRecord::image_array_layers},
    {"maxStorageBufferRange", &DeviceLimitsRecord::storage_buffer_range},
    {"subgroupSize", &DeviceLimitsRecord::subgroup_size},
};
constexpr std::size_t kLimitKeyCount = std::size(kLimits32) + 4;  // + the two vectors, the size, the features

struct Feature {
  const char* key;
  bool Rgba32fFeatures::*field;
};
constexpr Feature kFeatures[] = {
    {"sampled_image", &Rgba32fFeatures::sampled_image},
    {"sampled_image_filter_linear", &Rgba32fFeatures::sampled_image_filter_linear},
    {"storage_image", &Rgba32fFeatures::storage_image},
    {"blit_src", &Rgba32fFeatures::blit_src},
    {"blit_dst", &Rgba32fFeatures::blit_dst},
};

// ---- writing ----

json limits_json(const DeviceLimitsRecord& l) {
  json out = json::object();
  for (const Limit32& k : kLimits32) out[k.key] = l.*k.field;
  out["maxComputeWorkGroupSize"] = l.workgroup_size;
  out["maxComputeWorkGroupCount"] = l.workgroup_count;
  out["maxMemoryAllocationSize"] = l.max_memory_allocation_size;
  json features = json::object();
  for (const Feature& f : kFeatures) features[f.key] = l.rgba32f_optimal_tiling.*f.field;
  out["rgba32f_optimal_tiling"] = features;
  return out;
}

json verdict_json(const SupportVerdict& v) { return json{{"runs", v.runs}, {"reason", v.reason}}; }

// ---- reading ----

// A non-negative integer (a parsed file holds one as unsigned, a document built in memory as
// signed) of at most `max`.
uint64_t unsigned_member(const JsonReader& r, const json& object, const std::string& parent, std::string_view key,
                         uint64_t max = std::numeric_limits<uint64_t>::max()) {
  const json& v = r.member(object, parent, key);
  if (!v.is_number_integer() || (!v.is_number_unsigned() && v.get<int64_t>() < 0) || v.get<uint64_t>() > max)
    r.wrong_type(v, r.child(parent, key), max == UINT32_MAX ? "an unsigned 32-bit integer" : "a non-negative integer");
  return v.get<uint64_t>();
}

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

std::array<uint32_t, 3> vector3(const JsonReader& r, const json& object, const std::string& parent,
                                std::string_view key) {
  const json& a = r.array(object, parent, key, 3);
  const std::string path = r.child(parent, key);
  std::array<uint32_t, 3> out{};
  for (std::size_t i = 0; i < 3; ++i) {
    if (!a[i].is_number_unsigned() || a[i].get<uint64_t>() > UINT32_MAX)
      r.wrong_type(a[i], r.element(path, i), "an unsigned 32-bit integer");
    out[i] = a[i].get<uint32_t>();
  }
  return out;
}

DeviceLimitsRecord read_limits(const JsonReader& r, const json& l, const std::string& p) {
  DeviceLimitsRecord out;
  for (const Limit32& k : kLimits32) out.*k.field = r.uint32(l, p, k.key);
  out.workgroup_size = vector3(r, l, p, "maxComputeWorkGroupSize");
  out.workgroup_count = vector3(r, l, p, "maxComputeWorkGroupCount");
  out.max_memory_allocation_size = unsigned_member(r, l, p, "maxMemoryAllocationSize");
  const json& f = r.object(l, p, "rgba32f_optimal_tiling");
  const std::string fp = r.child(p, "rgba32f_optimal_tiling");
  r.only_keys(f, fp, {"sampled_image", "sampled_image_filter_linear", "storage_image", "blit_src", "blit_dst"});
  for (const Feature& k : kFeatures) out.rgba32f_optimal_tiling.*k.field = r.boolean(f, fp, k.key);
  // Every key above is required, so one more is one the model would drop: refuse it.
  if (l.size() != kLimitKeyCount)
    for (const auto& [key, value] : l.items()) {
      bool known = key == "maxComputeWorkGroupSize" || key == "maxComputeWorkGroupCount" ||
                   key == "maxMemoryAllocationSize" || key == "rgba32f_optimal_tiling";
      for (const Limit32& k : kLimits32) known = known || key == k.key;
      if (!known) r.fail(r.child(p, key), "is not a known limit");
    }
  return out;
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
  if (d.limits) out["limits"] = limits_json(*d.limits);
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
  out.device_local_bytes = unsigned_member(r, d, p, "device_local_bytes");
  if (d.contains("limits")) out.limits = read_limits(r, r.object(d, p, "limits"), r.child(p, "limits"));
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
  return devices_from_json(json(read_json_file(path, "the devices document")), path.string());
}

std::string devices_file_text(const DevicesDocument& doc) {
  const json out = to_json(doc);
  require_conforming(nlohmann::ordered_json(out), json(embedded_json(kDevicesSchemaFile, "the devices schema")),
                     "the devices document", embedded_file_label(kDevicesSchemaFile));
  return out.dump(2) + "\n";
}

}  // namespace vsgl
