#include "harness/vk/spirv_reflection.hpp"

#include <algorithm>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

namespace vsgl {
namespace {

// SPIR-V opcodes and enumerants used below (SPIR-V 1.5 specification, section 3).
enum : uint32_t {
  kOpExecutionMode = 16, kOpTypeBool = 20, kOpTypeInt = 21, kOpTypeFloat = 22, kOpTypeVector = 23,
  kOpTypeMatrix = 24, kOpTypeImage = 25, kOpTypeSampler = 26, kOpTypeSampledImage = 27, kOpTypeArray = 28,
  kOpTypeRuntimeArray = 29, kOpTypeStruct = 30, kOpTypePointer = 32, kOpConstantTrue = 41, kOpConstantFalse = 42,
  kOpConstant = 43, kOpConstantComposite = 44, kOpSpecConstantTrue = 48, kOpSpecConstantFalse = 49,
  kOpSpecConstant = 50, kOpSpecConstantComposite = 51, kOpSpecConstantOp = 52, kOpVariable = 59, kOpDecorate = 71, kOpMemberDecorate = 72,
  kOpCompositeExtract = 81, kOpIAdd = 128, kOpISub = 130, kOpIMul = 132, kOpUDiv = 134, kOpSDiv = 135,
  kOpShiftRightLogical = 194, kOpShiftLeftLogical = 196,
  kDecorationSpecId = 1, kDecorationBlock = 2, kDecorationBufferBlock = 3, kDecorationArrayStride = 6,
  kDecorationMatrixStride = 7, kDecorationBuiltIn = 11, kDecorationBinding = 33, kDecorationDescriptorSet = 34,
  kDecorationOffset = 35, kBuiltInWorkgroupSize = 25, kExecutionModeLocalSize = 17,
  kStorageClassUniformConstant = 0, kStorageClassUniform = 2, kStorageClassWorkgroup = 4,
  kStorageClassPushConstant = 9, kStorageClassStorageBuffer = 12, kDimBuffer = 5,
};

struct Inst {
  uint32_t op = 0;
  std::vector<uint32_t> args;  // operands after the result id
};

}  // namespace

KernelInterface reflect_kernel(std::span<const uint32_t> words, const std::map<uint32_t, uint32_t>& spec_values) {
  if (words.size() < 5 || words[0] != 0x07230203u) throw std::runtime_error("not a SPIR-V module");
  std::map<uint32_t, Inst> defs;
  std::map<uint32_t, std::map<uint32_t, uint32_t>> member_offsets, matrix_strides;
  std::map<uint32_t, uint32_t> array_strides, spec_ids, sets, bindings;
  std::map<uint32_t, bool> block, buffer_block;
  std::optional<uint32_t> workgroup_builtin;
  std::vector<uint32_t> local_size;
  struct Var {
    uint32_t pointer_type, id, storage;
  };
  std::vector<Var> vars;
  for (std::size_t i = 5; i < words.size();) {
    const uint32_t count = words[i] >> 16, op = words[i] & 0xFFFFu;
    if (count == 0 || i + count > words.size()) throw std::runtime_error("malformed SPIR-V");
    const std::vector<uint32_t> a(words.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                                  words.begin() + static_cast<std::ptrdiff_t>(i + count));
    i += count;
    switch (op) {
      case kOpExecutionMode:
        if (a.at(1) == kExecutionModeLocalSize) local_size.assign(a.begin() + 2, a.end());
        break;
      case kOpDecorate:
        switch (a.at(1)) {
          case kDecorationSpecId: spec_ids[a.at(0)] = a.at(2); break;
          case kDecorationArrayStride: array_strides[a.at(0)] = a.at(2); break;
          case kDecorationBlock: block[a.at(0)] = true; break;
          case kDecorationBufferBlock: buffer_block[a.at(0)] = true; break;
          case kDecorationBinding: bindings[a.at(0)] = a.at(2); break;
          case kDecorationDescriptorSet: sets[a.at(0)] = a.at(2); break;
          case kDecorationBuiltIn:
            if (a.at(2) == kBuiltInWorkgroupSize) workgroup_builtin = a.at(0);
            break;
          default: break;
        }
        break;
      case kOpMemberDecorate:
        if (a.at(2) == kDecorationOffset) member_offsets[a.at(0)][a.at(1)] = a.at(3);
        if (a.at(2) == kDecorationMatrixStride) matrix_strides[a.at(0)][a.at(1)] = a.at(3);
        break;
      case kOpTypeBool: case kOpTypeInt: case kOpTypeFloat: case kOpTypeVector: case kOpTypeMatrix:
      case kOpTypeImage: case kOpTypeSampler: case kOpTypeSampledImage: case kOpTypeArray:
      case kOpTypeRuntimeArray: case kOpTypeStruct: case kOpTypePointer:
        defs[a.at(0)] = {op, {a.begin() + 1, a.end()}};
        break;
      case kOpConstantTrue: case kOpConstantFalse: case kOpConstant: case kOpConstantComposite:
      case kOpSpecConstantTrue: case kOpSpecConstantFalse: case kOpSpecConstant: case kOpSpecConstantComposite:
      case kOpSpecConstantOp:
        defs[a.at(1)] = {op, {a.begin() + 2, a.end()}};
        break;
      case kOpVariable: vars.push_back({a.at(0), a.at(1), a.at(2)}); break;
      default: break;
    }
  }

  const auto def = [&](uint32_t id) -> const Inst& {
    const auto it = defs.find(id);
    if (it == defs.end()) throw std::runtime_error("SPIR-V id " + std::to_string(id) + " is not a type or constant");
    return it->second;
  };
  // The value of a scalar constant, specialized; spec-constant expressions of the integer
  // operations glslang emits for array sizes (e.g. gl_WorkGroupSize.x * 2).
  std::function<uint32_t(uint32_t)> value_of = [&](uint32_t id) -> uint32_t {
    const Inst& c = def(id);
    if (c.op == kOpSpecConstantOp) {
      const uint32_t opcode = c.args.at(0);
      if (opcode == kOpCompositeExtract) return value_of(def(c.args.at(1)).args.at(c.args.at(2)));
      const uint32_t x = value_of(c.args.at(1)), y = value_of(c.args.at(2));
      switch (opcode) {
        case kOpIAdd: return x + y;
        case kOpISub: return x - y;
        case kOpIMul: return x * y;
        case kOpUDiv: case kOpSDiv:
          if (y == 0) throw std::runtime_error("a SPIR-V spec-constant division by zero");
          return x / y;
        case kOpShiftLeftLogical: return x << y;
        case kOpShiftRightLogical: return x >> y;
        default: throw std::runtime_error("a SPIR-V spec-constant operation not known here: " + std::to_string(opcode));
      }
    }
    const auto spec = spec_ids.find(id);
    const bool specializable = c.op == kOpSpecConstant || c.op == kOpSpecConstantTrue || c.op == kOpSpecConstantFalse;
    if (specializable && spec != spec_ids.end()) {
      const auto v = spec_values.find(spec->second);
      if (v != spec_values.end()) return v->second;
    }
    switch (c.op) {
      case kOpConstant: case kOpSpecConstant: return c.args.at(0);
      case kOpConstantTrue: case kOpSpecConstantTrue: return 1;
      case kOpConstantFalse: case kOpSpecConstantFalse: return 0;
      default: throw std::runtime_error("a SPIR-V array size or work-group size that is not a scalar constant");
    }
  };
  // Bytes of a type: block members at their offsets, arrays at their stride; shared variables
  // (no layout decorations) packed at their scalar sizes, booleans as 4 bytes.
  std::function<uint32_t(uint32_t, uint32_t)> size_of = [&](uint32_t type, uint32_t matrix_stride) -> uint32_t {
    const Inst& t = def(type);
    switch (t.op) {
      case kOpTypeBool: return 4;
      case kOpTypeInt: case kOpTypeFloat: return t.args.at(0) / 8;
      case kOpTypeVector: return t.args.at(1) * size_of(t.args.at(0), 0);
      case kOpTypeMatrix: return t.args.at(1) * (matrix_stride ? matrix_stride : size_of(t.args.at(0), 0));
      case kOpTypeArray: {
        const auto stride = array_strides.find(type);
        return value_of(t.args.at(1)) * (stride != array_strides.end() ? stride->second : size_of(t.args.at(0), 0));
      }
      case kOpTypeRuntimeArray: return 0;
      case kOpTypeStruct: {
        uint32_t end = 0, packed = 0;
        for (uint32_t m = 0; m < t.args.size(); ++m) {
          const auto ms = matrix_strides[type].find(m);
          const uint32_t size = size_of(t.args[m], ms == matrix_strides[type].end() ? 0 : ms->second);
          const auto off = member_offsets[type].find(m);
          end = std::max(end, (off == member_offsets[type].end() ? packed : off->second) + size);
          packed += size;
        }
        return end;
      }
      default: throw std::runtime_error("a SPIR-V type whose size is not known here");
    }
  };

  KernelInterface out;
  for (const Var& v : vars) {
    const uint32_t pointee = def(v.pointer_type).args.at(1);
    if (v.storage == kStorageClassPushConstant) {
      out.push_constant_bytes = std::max(out.push_constant_bytes, size_of(pointee, 0));
      continue;
    }
    if (v.storage == kStorageClassWorkgroup) {
      out.shared_memory_bytes += size_of(pointee, 0);
      continue;
    }
    if (v.storage != kStorageClassUniformConstant && v.storage != kStorageClassUniform &&
        v.storage != kStorageClassStorageBuffer)
      continue;
    ReflectedDescriptor d;
    d.set = sets.count(v.id) ? sets[v.id] : 0;
    d.binding = bindings.count(v.id) ? bindings[v.id] : 0;
    uint32_t type = pointee;
    if (def(type).op == kOpTypeArray) {
      d.count = value_of(def(type).args.at(1));
      type = def(type).args.at(0);
    } else if (def(type).op == kOpTypeRuntimeArray) {
      throw std::runtime_error("a runtime-sized descriptor array (descriptor indexing is not used here)");
    }
    const Inst& t = def(type);
    if (v.storage == kStorageClassStorageBuffer || (v.storage == kStorageClassUniform && buffer_block[type]))
      d.type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    else if (v.storage == kStorageClassUniform && block[type])
      d.type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    else if (t.op == kOpTypeSampler)
      d.type = VK_DESCRIPTOR_TYPE_SAMPLER;
    else if (t.op == kOpTypeSampledImage)
      d.type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    else if (t.op == kOpTypeImage) {
      // OpTypeImage operands: sampled type, Dim, Depth, Arrayed, MS, Sampled (1 sampled, 2 storage).
      const bool storage = t.args.at(5) == 2, buffer = t.args.at(1) == kDimBuffer;
      d.type = buffer ? (storage ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER : VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER)
                      : (storage ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE);
    } else {
      throw std::runtime_error("a SPIR-V resource variable of a kind not known here");
    }
    out.descriptors.push_back(d);
  }
  if (workgroup_builtin) {
    const Inst& c = def(*workgroup_builtin);
    for (int k = 0; k < 3; ++k) out.workgroup_size[k] = value_of(c.args.at(static_cast<std::size_t>(k)));
  } else if (local_size.size() == 3) {
    for (int k = 0; k < 3; ++k) out.workgroup_size[k] = local_size[static_cast<std::size_t>(k)];
  }
  std::sort(out.descriptors.begin(), out.descriptors.end(), [](const auto& x, const auto& y) {
    return x.set != y.set ? x.set < y.set : x.binding < y.binding;
  });
  return out;
}

}  // namespace vsgl
