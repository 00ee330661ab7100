#pragma once
// A validator for the subset of JSON Schema (draft 2020-12 keywords) that
// results/schema/table.schema.json uses: type (a name or a list of names), properties, required,
// additionalProperties (boolean or schema), items (one schema), minItems, enum, const, minimum,
// exclusiveMinimum, $defs at the root and $ref to "#/$defs/NAME", and the annotations $schema,
// $id, title and description. Any other keyword anywhere in the schema is an error, so the
// schema cannot silently ask for something this validator ignores.
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace vsgl {

// Every violation as "JSON-pointer: problem"; empty when `doc` conforms. Throws
// std::invalid_argument listing schema_subset_problems(schema) when there are any.
std::vector<std::string> validate_against_schema(const nlohmann::ordered_json& doc,
                                                 const nlohmann::ordered_json& schema);

// For a document this program wrote (a violation is a bug, not bad input): throws std::logic_error
// "<what> does not conform to <schema_name>:" followed by every violation, one per line.
void require_conforming(const nlohmann::ordered_json& doc, const nlohmann::ordered_json& schema,
                        const std::string& what, const std::string& schema_name);

// Walks every subschema of `schema` (properties, items, additionalProperties, $defs, and those
// under keywords outside the subset: allOf, anyOf, oneOf, not, if/then/else, definitions,
// patternProperties, prefixItems, ...) and returns each problem as "schema-pointer: problem": a
// keyword outside the subset, a malformed value of one inside it, a $ref naming no $defs entry.
// Empty: validate_against_schema enforces every keyword the schema has.
std::vector<std::string> schema_subset_problems(const nlohmann::ordered_json& schema);

// Throws std::invalid_argument naming the first non-finite number's JSON pointer (DESIGN.md §12: no
// NaN ever written). nlohmann::ordered_json would silently write NaN and infinities as null.
void require_finite_numbers(const nlohmann::ordered_json& doc);

}  // namespace vsgl
