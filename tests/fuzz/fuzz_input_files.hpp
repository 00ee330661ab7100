#pragma once
// Shared by the fuzz targets: the loaders under test read files, so each input is written to a
// private temporary directory (one per process, removed at exit) as the file(s) under test.
// A capture input is several files in one: gbuffer.exr, rsm.exr and capture.json, separated by
// kFilePartSeparator (tests/fuzz/capture.dict holds it, so the fuzzer keeps the layout).
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include <unistd.h>

namespace vsgl::fuzz {

inline constexpr std::string_view kFilePartSeparator = "\n--vsgl-fuzz-next-file--\n";

class ScratchDir {
 public:
  ScratchDir() {
    const char* base = std::getenv("TMPDIR");
    std::string templ = std::string(base && *base ? base : "/tmp") + "/vsgl-fuzz-XXXXXX";
    if (::mkdtemp(templ.data()) == nullptr) std::abort();
    path_ = templ;
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }

  // Writes `bytes` as `name` in the directory (replacing it).
  std::filesystem::path write(const std::string& name, std::string_view bytes) const {
    const std::filesystem::path p = path_ / name;
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) std::abort();
    return p;
  }
  void remove(const std::string& name) const {
    std::error_code ignored;
    std::filesystem::remove(path_ / name, ignored);
  }

 private:
  std::filesystem::path path_;
};

// The input cut at every separator (at most `max_parts` parts; the last takes the rest).
inline std::vector<std::string_view> split_parts(std::string_view input, std::size_t max_parts) {
  std::vector<std::string_view> parts;
  while (parts.size() + 1 < max_parts) {
    const std::size_t at = input.find(kFilePartSeparator);
    if (at == std::string_view::npos) break;
    parts.push_back(input.substr(0, at));
    input.remove_prefix(at + kFilePartSeparator.size());
  }
  parts.push_back(input);
  return parts;
}

}  // namespace vsgl::fuzz
