#pragma once
// The console/markdown rendering of a table document (table_json.hpp), laid out like the
// paper's Tables 1-3: a column per generator with the paper's number in the column beside it.
#include <string>

#include <nlohmann/json.hpp>

namespace vsgl {

std::string table_markdown(const nlohmann::ordered_json& table);

}  // namespace vsgl
