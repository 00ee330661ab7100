#include "harness/timing/run_provenance.hpp"

#include <cctype>
#include <nlohmann/json.hpp>

#include "harness/core/build_info.hpp"
#include "harness/core/version.hpp"

namespace vsgl {

nlohmann::json build_json() {
  const BuildInfo b = build_info();
  return nlohmann::json{
      {"vsgl_bench_version", kVersionString},
      {"git_commit", b.git_commit},
      {"git_dirty", b.git_dirty},
      {"compiler", compiler_description()},
#ifdef NDEBUG
      {"assertions", false},
#else
      {"assertions", true},
#endif
  };
}

std::string device_slug(const std::string& device_name) {
  std::string slug;
  for (char c : device_name) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u)) slug += static_cast<char>(std::tolower(u));
    else if (!slug.empty() && slug.back() != '-') slug += '-';
  }
  while (!slug.empty() && slug.back() == '-') slug.pop_back();
  return slug.empty() ? "device" : slug;
}

}  // namespace vsgl
