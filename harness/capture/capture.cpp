#include "harness/capture/capture.hpp"

#include "harness/core/content_hash.hpp"

#include <bit>
#include <cstdio>

namespace vsgl {
namespace {

constexpr std::array<const char*, kChannelCount> kCameraChannelNames = {
    "P.X", "P.Y", "P.Z", "valid", "N.X", "N.Y", "N.Z", "albedo_diffuse.R", "albedo_diffuse.G",
    "albedo_diffuse.B", "albedo_specular.R", "albedo_specular.G", "albedo_specular.B", "roughness",
    "pdf"};
constexpr std::array<const char*, kChannelCount> kLightChannelNames = {
    "P.X", "P.Y", "P.Z", "valid", "N.X", "N.Y", "N.Z", "flux_diffuse.R", "flux_diffuse.G",
    "flux_diffuse.B", "flux_specular.R", "flux_specular.G", "flux_specular.B", "roughness", "pdf"};

}  // namespace

std::span<const char* const> channel_names(ViewKind kind) {
  return kind == ViewKind::kCamera ? std::span<const char* const>(kCameraChannelNames)
                                   : std::span<const char* const>(kLightChannelNames);
}

const char* view_file_name(ViewKind kind) {
  return kind == ViewKind::kCamera ? "gbuffer.exr" : "rsm.exr";
}

const char* view_label(ViewKind kind) { return kind == ViewKind::kCamera ? "gbuffer" : "rsm"; }

void ViewImage::resize(ViewKind k, uint32_t w, uint32_t h) {
  kind = k;
  width = w;
  height = h;
  for (std::vector<float>& plane : planes) plane.assign(std::size_t{w} * h, 0.0f);
}

std::string plane_hash(const std::vector<float>& plane) {
  // The hash is defined over the little-endian bytes of the floats.
  static_assert(std::endian::native == std::endian::little);
  return bytes_hash(std::string_view(reinterpret_cast<const char*>(plane.data()), plane.size() * sizeof(float)));
}

std::string bytes_hash(std::string_view bytes) { return fnv1a64_text(bytes); }

}  // namespace vsgl
