#pragma once
// A small command-line reader: `--name value`, `--name=value` and `--flag`. Unknown or
// leftover options are usage errors, so a typo never silently falls back to a default.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vsgl::cli {

class Args {
 public:
  Args(int argc, char** argv, int first);
  explicit Args(std::vector<std::string> tokens) : tokens_(std::move(tokens)), used_(tokens_.size(), false) {}

  bool flag(const std::string& name);
  std::optional<std::string> value(const std::string& name);  // the last occurrence
  // Every occurrence, in order (an option that may be repeated: --capture A --capture B).
  std::vector<std::string> values(const std::string& name);
  std::string string(const std::string& name, const std::string& fallback);
  // "a,b,c" -> {"a", "b", "c"} (empty items dropped).
  std::vector<std::string> list(const std::string& name, const std::string& fallback);
  uint32_t u32(const std::string& name, uint32_t fallback, uint32_t min_value = 0);
  float positive_float(const std::string& name, float fallback);
  // "WxH" -> {W, H}
  std::pair<uint32_t, uint32_t> size(const std::string& name, std::pair<uint32_t, uint32_t> fallback);
  // Throws UsageError naming the first argument nobody asked for.
  void finish() const;

 private:
  std::vector<std::string> tokens_;
  std::vector<bool> used_;
};

}  // namespace vsgl::cli
