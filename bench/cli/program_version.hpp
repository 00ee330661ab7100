#pragma once
// The `--version` text of the programs: what the build was made from (harness/core/build_info.hpp:
// version, commit, compiler), the Vulkan headers it was compiled against, and the licence.
#include <string>

namespace vsgl::cli {

// The licence every program is distributed under (SPDX identifier); its text is LICENSE (in the
// .deb, /usr/share/doc/vsgl-bench/copyright).
inline constexpr const char* kLicence = "Apache-2.0";

// "1.3.239": VK_HEADER_VERSION_COMPLETE of the headers this build included; a driver may offer
// another Vulkan version, which `vsgl-bench devices` lists.
std::string vulkan_header_version();

std::string program_version_text(const std::string& program);

}  // namespace vsgl::cli
