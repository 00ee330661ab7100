#pragma once
// The Google Benchmark front ends' own options (vsgl-gbench, vsgl-mipbench): what Google
// Benchmark left in argv, as vsgl-bench's tokens — --vsgl_camera_vsgls=N becomes
// --camera-vsgls=N. Anything else is not ours: UsageError.
#include <string>
#include <vector>

namespace vsgl::cli {

std::vector<std::string> gbench_tokens(int argc, char** argv);

}  // namespace vsgl::cli
