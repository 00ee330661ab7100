#pragma once
// Files of the source tree built into the program (cmake/Embed.cmake; DESIGN.md §10): the paper's
// tables, the schemas, the scene presets and the sources Table 3 counts, so that a copied binary
// reads nothing from the checkout it was built in. Each is named by its path relative to the
// source tree ("results/paper/paper_tables.json").
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace vsgl {

namespace detail {
struct EmbeddedBytes {
  const char* name;
  const unsigned char* bytes;
  std::size_t size;
};
extern const EmbeddedBytes kEmbeddedFiles[];  // sorted by name (generated)
extern const std::size_t kEmbeddedFileCount;
}  // namespace detail

// The text of the embedded file `name`, or nullopt when no file of that name was embedded.
std::optional<std::string_view> embedded_file(std::string_view name);

// The names of every embedded file that starts with `prefix`, sorted.
std::vector<std::string> embedded_file_names(std::string_view prefix = {});

// How an embedded file is named in messages and outputs: "results/paper/paper_tables.json (built in)".
std::string embedded_file_label(std::string_view name);

// The embedded JSON file `name`, parsed. Throws InputError when there is none (a build that did not
// embed it) or it is not valid JSON, naming it and `what`.
nlohmann::ordered_json embedded_json(std::string_view name, const std::string& what);

// A JSON input a user may override (--paper, --schema): `file` when given (read_json_file, with
// `hint` on a read failure), else the embedded `built_in`.
nlohmann::ordered_json json_file_or_built_in(const std::optional<std::filesystem::path>& file,
                                             std::string_view built_in, const std::string& what,
                                             const std::string& hint);
// The name of that input in messages and outputs: the file, or embedded_file_label(built_in).
std::string file_or_built_in_name(const std::optional<std::filesystem::path>& file, std::string_view built_in);

}  // namespace vsgl
