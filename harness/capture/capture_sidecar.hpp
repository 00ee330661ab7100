#pragma once
// The capture sidecar (capture.json, DESIGN.md §3): the metadata and what it says about each view
// file, written as JSON and read back with every field checked.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>

#include "harness/capture/capture.hpp"

namespace vsgl {

inline constexpr const char* kSidecarName = "capture.json";

// What the sidecar says about one view.
struct ViewRecord {
  std::string file;
  uint32_t width = 0;
  uint32_t height = 0;
  bool has_pdf = true;
  std::array<std::string, kChannelCount> hashes;
};

struct SidecarContents {
  CaptureMeta meta;  // hashes included
  ViewRecord gbuffer, rsm;
};

// The sidecar of `capture` with the hashes of `meta`, as JSON text.
std::string sidecar_text(const CaptureMeta& meta, const Capture& capture);

// Reads and checks DIR/capture.json; throws InputError naming the file and the key.
SidecarContents read_sidecar(const std::filesystem::path& path);

}  // namespace vsgl
