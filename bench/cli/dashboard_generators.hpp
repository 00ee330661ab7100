#pragma once
// The dashboard's view of the descriptor table (compare/ sits beside generators/, not above it, so
// the front ends hand the page what it shows of each generator).
#include <vector>

#include "harness/compare/dashboard_page.hpp"

namespace vsgl::cli {

std::vector<DashboardGenerator> dashboard_generators();

}  // namespace vsgl::cli
