#include "harness/core/sorted_json.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace vsgl {

nlohmann::ordered_json sorted_keys(const nlohmann::ordered_json& value) {
  if (value.is_array()) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const auto& element : value) out.push_back(sorted_keys(element));
    return out;
  }
  if (!value.is_object()) return value;
  std::vector<std::string> keys;
  for (auto it = value.begin(); it != value.end(); ++it) keys.push_back(it.key());
  std::sort(keys.begin(), keys.end());
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const std::string& key : keys) out[key] = sorted_keys(value.at(key));
  return out;
}

}  // namespace vsgl
