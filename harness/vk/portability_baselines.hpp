#pragma once
// Two baselines a kernel's needs are audited against (DESIGN.md §9), as data:
//  - the limits every Vulkan 1.2 implementation must meet (the Vulkan 1.2 specification, table
//    "Required Limits", and VkPhysicalDeviceMaintenance3Properties::maxMemoryAllocationSize);
//  - the Khronos Vulkan-Profiles profile VP_LUNARG_desktop_baseline_2023 (profile version 2,
//    Vulkan 1.2.148; profiles/LunarG/VP_LUNARG_desktop_baseline.json of KhronosGroup/Vulkan-Profiles,
//    its VP_LUNARG_desktop_baseline_2023_block), what desktop GPUs of 2023 are expected to meet.
// Only the limits vsgl-bench's kernels and captures depend on are listed.
#include "harness/vk/device_limits.hpp"

namespace vsgl {

const DeviceLimits& vulkan12_required_limits();
const DeviceLimits& desktop_baseline_2023_limits();
inline constexpr const char* kDesktopBaselineName = "VP_LUNARG_desktop_baseline_2023 (version 2)";

}  // namespace vsgl
