#pragma once
// What one point of `vsgl-bench sweep` changes (DESIGN.md §10.1): each axis's value at the point
// mapped onto the tables' options (N, K, the k-means iterations), the recorded sizes (G-buffer,
// RSM) or γ (the PDF sharpness), and the time budget's share as the point's time cap.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "harness/sweep/sweep_options.hpp"

namespace vsgl {

struct SweepPointSetup {
  std::size_t point = 0;                 // its position in the axes' product
  std::vector<std::size_t> value_index;  // one per axis
  std::string where;                     // "vsgls=16, K=2"
  TablesOptions tables;                  // the sweep's, with the point's N, K, iterations and time cap
  RecordSizes sizes;                     // the sweep's, with the point's G-buffer and RSM sizes
  std::optional<double> gamma;           // on a pdf-sharpness axis
};

// `points`: how many points the sweep has (the budget is split evenly over them).
SweepPointSetup sweep_point_setup(const SweepOptions& options, std::size_t point,
                                  const std::vector<std::size_t>& value_index, std::size_t points);

}  // namespace vsgl
