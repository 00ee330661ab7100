#pragma once
// The suite's content hash: 64-bit FNV-1a over bytes, written "fnv1a64:<16 hex>". Captures name
// their planes and files by it, scenes their model files, the visibility layer its occluders; one
// definition so that the same bytes always give the same name.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace vsgl {

// Over several byte ranges in turn.
struct Fnv1a64 {
  uint64_t hash = 14695981039346656037ull;
  void add(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) {
      hash ^= p[i];
      hash *= 1099511628211ull;
    }
  }
  std::string text() const {
    char buf[8 + 16 + 1];
    std::snprintf(buf, sizeof buf, "fnv1a64:%016llx", static_cast<unsigned long long>(hash));
    return buf;
  }
};

inline std::string fnv1a64_text(std::string_view bytes) {
  Fnv1a64 h;
  h.add(bytes.data(), bytes.size());
  return h.text();
}

}  // namespace vsgl
