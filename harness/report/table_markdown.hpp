#pragma once
// The console/markdown rendering of a table (formats/table_model.hpp), laid out like the paper's
// Tables 1-3: a column per generator with the paper's number in the column beside it.
#include <string>

#include <nlohmann/json.hpp>

#include "harness/formats/table_model.hpp"

namespace vsgl {

// Throws InputError naming a section the rendering needs and the model lacks.
std::string table_markdown(const TableModel& table);
// The same from a table document (read with table_model_from_json).
std::string table_markdown(const nlohmann::ordered_json& table);

}  // namespace vsgl
