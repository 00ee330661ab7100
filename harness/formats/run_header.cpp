#include "harness/formats/run_header.hpp"

#include <cstdint>
#include <string_view>

#include "harness/core/json_reader.hpp"
#include "harness/core/sorted_json.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

// An index that may be -1 for none.
int64_t index_or_none(const JsonReader& r, const ojson& object, const std::string& parent, std::string_view key) {
  const ojson& v = r.member(object, parent, key);
  const bool fits =
      v.is_number_unsigned() ? v.get<uint64_t>() <= UINT32_MAX : v.is_number_integer() && v.get<int64_t>() >= -1;
  if (!fits) r.wrong_type(v, r.child(parent, key), "an index or -1");
  return v.get<int64_t>();
}

void require_object(const JsonReader& r, const ojson& value, const std::string& path) {
  if (!value.is_object()) r.wrong_type(value, path, "an object");
}

}  // namespace

nlohmann::ordered_json to_json(const DeviceRecord& d) {
  ojson out{{"index", d.index},
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
  return sorted_keys(out);
}

nlohmann::ordered_json to_json(const BuildRecord& b) {
  return sorted_keys(ojson{{"vsgl_bench_version", b.vsgl_bench_version},
                           {"git_commit", b.git_commit},
                           {"git_dirty", b.git_dirty},
                           {"compiler", b.compiler},
                           {"assertions", b.assertions}});
}

nlohmann::ordered_json to_json(const RunRecord& r) {
  ojson out{{"started_utc", r.started_utc},
            {"validation_layer", r.validation_layer},
            {"quick", r.quick},
            {"protocol_compliant", r.protocol_compliant},
            {"clocks_locked_claimed", r.clocks_locked_claimed}};
  if (r.clocks_note) out["clocks_note"] = *r.clocks_note;
  if (!r.altered_generators.empty()) out["altered_generators"] = r.altered_generators;  // not a measurement
  return out;
}

DeviceRecord device_record_from_json(const JsonReader& r, const nlohmann::ordered_json& d, const std::string& p) {
  require_object(r, d, p);
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

BuildRecord build_record_from_json(const JsonReader& r, const nlohmann::ordered_json& b, const std::string& p) {
  require_object(r, b, p);
  r.only_keys(b, p, {"vsgl_bench_version", "git_commit", "git_dirty", "compiler", "assertions"});
  return {r.string(b, p, "vsgl_bench_version"), r.string(b, p, "git_commit"), r.boolean(b, p, "git_dirty"),
          r.string(b, p, "compiler"), r.boolean(b, p, "assertions")};
}

RunRecord run_record_from_json(const JsonReader& r, const nlohmann::ordered_json& run, const std::string& p) {
  require_object(r, run, p);
  r.only_keys(run, p,
              {"started_utc", "validation_layer", "quick", "protocol_compliant", "clocks_locked_claimed", "clocks_note",
               "altered_generators"});
  RunRecord out;
  out.started_utc = r.string(run, p, "started_utc");
  out.validation_layer = r.boolean(run, p, "validation_layer");
  out.quick = r.boolean(run, p, "quick");
  out.protocol_compliant = r.boolean(run, p, "protocol_compliant");
  out.clocks_locked_claimed = r.boolean(run, p, "clocks_locked_claimed");
  out.clocks_note = r.optional_string(run, p, "clocks_note");
  if (run.contains("altered_generators")) {
    const std::string ap = r.child(p, "altered_generators");
    const ojson& altered = r.array(run, p, "altered_generators");
    for (std::size_t i = 0; i < altered.size(); ++i) {
      if (!altered[i].is_string()) r.wrong_type(altered[i], r.element(ap, i), "a generator name");
      out.altered_generators.push_back(altered[i].get<std::string>());
    }
  }
  return out;
}

}  // namespace vsgl
