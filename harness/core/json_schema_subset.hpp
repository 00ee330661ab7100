#pragma once
// A validator for the subset of JSON Schema (draft 2020-12 keywords) that
// results/schema/table.schema.json uses: type (a name or a list of names), properties, required,
// additionalProperties (boolean or schema), items, minItems, enum, const, minimum,
// exclusiveMinimum, and $ref to "#/$defs/NAME". Any other keyword in the schema is an error, so
// the schema cannot silently ask for something this validator ignores.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace vsgl {

// Every violation as "JSON-pointer: problem"; empty when `doc` conforms.
std::vector<std::string> validate_against_schema(const nlohmann::json& doc, const nlohmann::json& schema);

// Throws std::invalid_argument naming the first non-finite number's JSON pointer (DESIGN.md §12: no
// NaN ever written). nlohmann::json would silently write NaN and infinities as null.
void require_finite_numbers(const nlohmann::ordered_json& doc);

}  // namespace vsgl
