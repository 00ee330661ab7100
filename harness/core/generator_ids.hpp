#pragma once
// The stable id of every generator (DESIGN.md §6), spelled once. The descriptors
// (generators/generator_descriptor.hpp) take their `name` from here, and code below the
// generators layer (the document models, the CPU references) or code about one given column
// (a claim about the modified FIS) names a generator only through these constants.
#include <string_view>

namespace vsgl {

inline constexpr std::string_view kFisTok15 = "fis_tok15";        // [Tok15] FIS, Eq. 1 and 4
inline constexpr std::string_view kFisModified = "fis_modified";  // the paper's, Eq. 3 and 5
inline constexpr std::string_view kKmeans2d = "kmeans_2d";
inline constexpr std::string_view kKmeans3d = "kmeans_3d";
// Beyond the paper: the k-means generators with a segmented-reduction sum (DESIGN.md §6.2).
inline constexpr std::string_view kKmeans2dSegsum = "kmeans_2d_segsum";
inline constexpr std::string_view kKmeans3dSegsum = "kmeans_3d_segsum";

}  // namespace vsgl
