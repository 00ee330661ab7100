#pragma once
// What each algorithm predicts for the cost growth of a phase along a sweep axis (DESIGN.md
// §10.1), for judge_growth: a slope and the reason, or nothing where the algorithm says nothing
// firm (k-means over N: its grid grows with N; anything under a PDF change for k-means).
#include <optional>
#include <string>

#include "harness/core/growth_fit.hpp"
#include "harness/generators/generator_descriptor.hpp"
#include "harness/sweep/sweep_axis.hpp"

namespace vsgl {

// Bands around the predicted slopes: fixed costs (launches, barriers) bend a log-log line at small
// sizes, so a linear phase is accepted from 0.85 and a constant one up to ±0.1.
inline constexpr double kLinearTolerance = 0.15;
inline constexpr double kConstantTolerance = 0.1;

// `view` "camera_view" | "light_view"; `phase` a phase of the family or "total".
std::optional<GrowthExpectation> expected_growth(SweepParameter parameter, GeneratorFamily family,
                                                 const std::string& view, const std::string& phase);

// Whether the parameter changes the input or the work of a view (gbuffer: the camera view only).
bool parameter_touches_view(SweepParameter parameter, const std::string& view);

}  // namespace vsgl
