// Shared by C++ and GLSL: the push-constant blocks and work-group sizes of the kernels are
// declared once, in kernels/include/interface/*.h, and included by both the shader and its host
// code (as nvpro-samples do). In GLSL the structs become push-constant blocks:
//     layout(push_constant) uniform PushBlock { FisMipPush pc; };
// and the work-group sizes specialization constants set by the host:
//     layout(local_size_x_id = 0, local_size_y_id = 1) in;
// In C++ the same structs are what vkCmdPushConstants sends; VSGL_LAYOUT checks their size and
// the 16-byte alignment std430 gives to vec4 and mat4 members, so a change on one side that
// does not fit the other fails to compile.
#ifndef VSGL_INTEROP_H
#define VSGL_INTEROP_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#define VSGL_INTERFACE_BEGIN namespace vsgl::gpu {
#define VSGL_INTERFACE_END }
namespace vsgl::gpu {
using uint = std::uint32_t;
using vec4 = glm::vec4;
using mat4 = glm::mat4;
}  // namespace vsgl::gpu
// vec4 / mat4 members sit at 16-byte offsets (std430); the struct's size is what the shader sees.
#define VSGL_LAYOUT(type, bytes)                                                           \
  static_assert(sizeof(type) == (bytes), #type ": size differs from the GLSL block");     \
  static_assert(sizeof(type) <= 128, #type ": Vulkan guarantees only 128 bytes of push constants")
#define VSGL_VEC4_AT(type, member, offset)                                                 \
  static_assert(offsetof(type, member) == (offset) && (offset) % 16 == 0,                  \
                #type "." #member ": a vec4/mat4 member must sit at this 16-byte offset")
#define VSGL_CONST constexpr
#else
#define VSGL_INTERFACE_BEGIN
#define VSGL_INTERFACE_END
// GLSL has no static_assert; these become constants (never used, so no code), which also
// consumes the `;` that follows each use (GLSL before 4.60 rejects an empty declaration).
#define VSGL_LAYOUT(type, bytes) const uint vsgl_size_of_##type = uint(bytes)
#define VSGL_VEC4_AT(type, member, offset) const uint vsgl_offset_of_##type##_##member = uint(offset)
#define VSGL_CONST const
#endif

#endif  // VSGL_INTEROP_H
