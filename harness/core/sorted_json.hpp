#pragma once
// The key order of the documents that were first written as nlohmann::json, which sorts its keys:
// the device object of every document, the devices, verify and quality documents. Every document is
// an nlohmann::ordered_json now; sorting keeps those files as they always were, byte for byte.
#include <nlohmann/json.hpp>

namespace vsgl {

// `value` with the keys of every object in it, at any depth, in sorted order.
nlohmann::ordered_json sorted_keys(const nlohmann::ordered_json& value);

}  // namespace vsgl
