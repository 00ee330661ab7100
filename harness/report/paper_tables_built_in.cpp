// Apart from paper_tables.cpp, which the fuzz targets build without the embedded files.
#include "harness/core/embedded_files.hpp"
#include "harness/report/paper_tables.hpp"

namespace vsgl {

nlohmann::ordered_json paper_tables_or_built_in(const std::optional<std::filesystem::path>& file) {
  if (file) return load_paper_tables(*file);
  nlohmann::ordered_json doc = embedded_json(kPaperTablesFile, "the paper's tables");
  check_paper_tables(doc, embedded_file_label(kPaperTablesFile));
  return doc;
}

}  // namespace vsgl
