#pragma once
// The verify document (`vsgl-bench verify --json`, results/schema/verify.schema.json, DESIGN.md
// §11) as one typed model: the capture checked, the device, and every check with its measured
// error and tolerance. The command fills it from its checks (verify/check_result.hpp) and writes
// it; the tests read every committed file into it and write it back unchanged.
//
// Files written before measurements existed (results/nvidia-h100-80gb-hbm3) have no `kind` on a
// check, every one a check with a tolerance; the model keeps that absence and writes it back.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/formats/devices_model.hpp"

namespace vsgl {

inline constexpr const char* kVerifySchemaFile = "results/schema/verify.schema.json";

enum class VerifyCheckKind {
  kCheck,        // judged: passes when measured <= tolerance
  kMeasurement,  // reported beside its expectation, never a failure
};

struct VerifyCheck {
  std::string view;       // "camera_view", "light_view", or "" (device-wide)
  std::string generator;  // a generator id (core/generator_ids.hpp) or "sampler"; FIS: "<id>[texture/blit]"
  std::string check;      // "pyramid", "eq3_residual", ...
  std::optional<VerifyCheckKind> kind;  // absent in older files: a check
  // The error, ratio deviation or count; NaN (null in the file) when the GPU gave a non-finite
  // one, which fails the check.
  double measured = 0;
  std::optional<double> tolerance;  // a check's
  std::optional<double> expected;   // a measurement's
  bool passed = false;
  std::string detail;  // what `measured` is, in words, with context numbers

  bool is_measurement() const { return kind == VerifyCheckKind::kMeasurement; }
};

struct VerifyDocument {
  std::string capture;  // the capture directory as given on the command line
  std::string scene;    // the capture's scene name
  DeviceRecord device;  // formats/run_header.hpp
  std::vector<VerifyCheck> checks;  // in the order run: FIS, then k-means
};

// The keys sorted, as the files always had them (core/sorted_json.hpp).
nlohmann::ordered_json to_json(const VerifyCheck& check);
nlohmann::ordered_json to_json(const VerifyDocument& doc);

// Every failure an InputError "<where>: <JSON pointer>: <problem>".
VerifyDocument verify_from_json(const nlohmann::ordered_json& doc, const std::string& where);
VerifyDocument read_verify_file(const std::filesystem::path& path);

// The file's text (2-space indent, a final newline), once the document conforms to the built-in
// verify schema (std::logic_error otherwise: a bug).
std::string verify_file_text(const VerifyDocument& doc);

}  // namespace vsgl
