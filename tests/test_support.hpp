#pragma once
// What many suites need: a temporary directory that cleans up after itself, readers of
// whole files that name the path when they cannot, the checkout and synthetic image layers.
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <random>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace vsgl::test {

// A fresh, empty directory <system temp>/vsgl_<name>_XXXXXX (mkdtemp; on Windows random names
// until one is new: unique even across concurrent test processes and reruns), removed with
// everything in it on destruction.
class TempDir {
 public:
  explicit TempDir(std::string_view name = "test") {
    std::string pattern = (std::filesystem::temp_directory_path() / ("vsgl_" + std::string(name) + "_XXXXXX")).string();
#ifdef _WIN32
    // No mkdtemp: random names until one is new (create_directory is false for an existing one).
    std::random_device random;
    for (int attempt = 0; attempt < 100 && path_.empty(); ++attempt) {
      std::filesystem::path candidate = pattern.substr(0, pattern.size() - 6) + std::to_string(random() % 1000000);
      if (std::filesystem::create_directory(candidate)) path_ = candidate;
    }
    if (path_.empty()) throw std::runtime_error("cannot create a temporary directory " + pattern);
#else
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    if (::mkdtemp(buffer.data()) == nullptr)
      throw std::system_error(errno, std::generic_category(), "cannot create a temporary directory " + pattern);
    path_ = buffer.data();
#endif
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::filesystem::path& p) const { return path_ / p; }

 private:
  std::filesystem::path path_;
};

// The file's bytes; throws std::runtime_error naming the path when it cannot be read.
inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The file parsed as JSON; throws naming the path when it cannot be read or parsed.
inline nlohmann::ordered_json read_json(const std::filesystem::path& path) {
  const std::string text = read_text(path);
  try {
    return nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::ordered_json::parse_error& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

// The checkout the tests compare against (the programs themselves never read it: DESIGN.md §10).
// One definition for every suite, so that suites compiled together in one unity batch share it.
inline const std::filesystem::path kSource = VSGL_SOURCE_DIR;

// A w x h image layer, row by row, texel (x, y) = f(x, y): synthetic RSM and pyramid inputs.
inline std::vector<glm::vec4> layer(uint32_t w, uint32_t h, const std::function<glm::vec4(uint32_t, uint32_t)>& f) {
  std::vector<glm::vec4> out;
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) out.push_back(f(x, y));
  return out;
}

}  // namespace vsgl::test
