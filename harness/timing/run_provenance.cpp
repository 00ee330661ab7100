#include "harness/timing/run_provenance.hpp"

#include <cctype>

namespace vsgl {

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
