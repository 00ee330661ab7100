#pragma once
// The key order of what was first written as an nlohmann::json, which sorts its keys: the device
// object of every document, and the devices, verify and quality documents. Every document is an
// nlohmann::ordered_json now (the one flavour); sorting keeps those files as they always were,
// byte for byte. Sorted keys also make two objects equal whatever order they were built in.
#include <nlohmann/json.hpp>

namespace vsgl {

// `value` with the keys of every object in it, at any depth, in sorted order.
nlohmann::ordered_json sorted_keys(const nlohmann::ordered_json& value);

}  // namespace vsgl
