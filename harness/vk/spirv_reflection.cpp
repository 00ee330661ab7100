#include "harness/vk/spirv_reflection.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

namespace vsgl {
namespace {

// SPIR-V opcodes and enumerants used below (SPIR-V 1.5 specification, section 3).
// clang-format off
enum : uint32_t {
  kOpEntryPoint = 15, kOpExecutionMode = 16, kOpTypeBool = 20, kOpTypeInt = 21, kOpTypeFloat = 22, kOpTypeVector = 23,
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
  kStorageClassPushConstant = 9, kStorageClassStorageBuffer = 12, kDimBuffer = 5, kExecutionModelGLCompute = 5,
};
// clang-format on

struct Inst {
  uint32_t op = 0;
  std::vector<uint32_t> args;  // operands after the result id
};

struct Variable {
  uint32_t pointer_type, id, storage;
};

// The instructions reflection reads, indexed by id: types and constants, decorations, the
// module's variables and what fixes its work-group size.
struct DecodedModule {
  std::map<uint32_t, Inst> defs;  // result id -> its type or constant instruction
  std::map<uint32_t, std::map<uint32_t, uint32_t>> member_offsets, matrix_strides;  // struct -> member -> value
  std::map<uint32_t, uint32_t> array_strides, spec_ids, sets, bindings;
  std::map<uint32_t, bool> block, buffer_block;
  std::optional<uint32_t> workgroup_builtin;  // the constant decorated WorkgroupSize
  std::vector<uint32_t> local_size;           // OpExecutionMode LocalSize x y z
  std::vector<Variable> vars;
  bool compute = false;

  const Inst& def(uint32_t id) const {
    const auto it = defs.find(id);
    if (it == defs.end()) throw std::runtime_error("SPIR-V id " + std::to_string(id) + " is not a type or constant");
    return it->second;
  }
  // A member decoration of `s` (OpMemberDecorate), if the module has one.
  static std::optional<uint32_t> member_value(const std::map<uint32_t, std::map<uint32_t, uint32_t>>& table, uint32_t s,
                                              uint32_t member) {
    const auto st = table.find(s);
    if (st == table.end()) return std::nullopt;
    const auto m = st->second.find(member);
    return m == st->second.end() ? std::nullopt : std::optional<uint32_t>(m->second);
  }
};

void decode_decoration(DecodedModule& m, const std::vector<uint32_t>& a) {
  switch (a.at(1)) {
    case kDecorationSpecId: m.spec_ids[a.at(0)] = a.at(2); break;
    case kDecorationArrayStride: m.array_strides[a.at(0)] = a.at(2); break;
    case kDecorationBlock: m.block[a.at(0)] = true; break;
    case kDecorationBufferBlock: m.buffer_block[a.at(0)] = true; break;
    case kDecorationBinding: m.bindings[a.at(0)] = a.at(2); break;
    case kDecorationDescriptorSet: m.sets[a.at(0)] = a.at(2); break;
    case kDecorationBuiltIn:
      if (a.at(2) == kBuiltInWorkgroupSize) m.workgroup_builtin = a.at(0);
      break;
    default: break;
  }
}

// One instruction: `op` with its operands `a` (the words after the opcode word).
void decode_instruction(DecodedModule& m, uint32_t op, const std::vector<uint32_t>& a) {
  switch (op) {
    case kOpEntryPoint: m.compute = m.compute || a.at(0) == kExecutionModelGLCompute; break;
    case kOpExecutionMode:
      if (a.at(1) == kExecutionModeLocalSize) m.local_size.assign(a.begin() + 2, a.end());
      break;
    case kOpDecorate: decode_decoration(m, a); break;
    case kOpMemberDecorate:
      if (a.at(2) == kDecorationOffset) m.member_offsets[a.at(0)][a.at(1)] = a.at(3);
      if (a.at(2) == kDecorationMatrixStride) m.matrix_strides[a.at(0)][a.at(1)] = a.at(3);
      break;
    case kOpTypeBool:
    case kOpTypeInt:
    case kOpTypeFloat:
    case kOpTypeVector:
    case kOpTypeMatrix:
    case kOpTypeImage:
    case kOpTypeSampler:
    case kOpTypeSampledImage:
    case kOpTypeArray:
    case kOpTypeRuntimeArray:
    case kOpTypeStruct:
    case kOpTypePointer: m.defs[a.at(0)] = {op, {a.begin() + 1, a.end()}}; break;
    case kOpConstantTrue:
    case kOpConstantFalse:
    case kOpConstant:
    case kOpConstantComposite:
    case kOpSpecConstantTrue:
    case kOpSpecConstantFalse:
    case kOpSpecConstant:
    case kOpSpecConstantComposite:
    case kOpSpecConstantOp: m.defs[a.at(1)] = {op, {a.begin() + 2, a.end()}}; break;
    case kOpVariable: m.vars.push_back({a.at(0), a.at(1), a.at(2)}); break;
    default: break;
  }
}

DecodedModule decode_module(std::span<const uint32_t> words) {
  if (words.size() < 5 || words[0] != 0x07230203u) throw std::runtime_error("not a SPIR-V module");
  DecodedModule m;
  for (std::size_t i = 5; i < words.size();) {
    const uint32_t count = words[i] >> 16, op = words[i] & 0xFFFFu;
    if (count == 0 || i + count > words.size()) throw std::runtime_error("malformed SPIR-V");
    decode_instruction(
        m, op,
        {words.begin() + static_cast<std::ptrdiff_t>(i) + 1, words.begin() + static_cast<std::ptrdiff_t>(i + count)});
    i += count;
  }
  return m;
}

// The module's constants and type sizes with the pipeline's specialization values applied.
class SpecializedModule {
 public:
  SpecializedModule(const DecodedModule& module, const std::map<uint32_t, uint32_t>& spec_values)
      : m_(module), spec_values_(spec_values) {}

  // The value of a scalar constant, specialized; spec-constant expressions of the integer
  // operations glslang emits for array sizes (e.g. gl_WorkGroupSize.x * 2).
  uint32_t value_of(uint32_t id) const {
    const Inst& c = m_.def(id);
    if (c.op == kOpSpecConstantOp) return operation_value(c);
    const auto spec = m_.spec_ids.find(id);
    const bool specializable = c.op == kOpSpecConstant || c.op == kOpSpecConstantTrue || c.op == kOpSpecConstantFalse;
    if (specializable && spec != m_.spec_ids.end()) {
      const auto v = spec_values_.find(spec->second);
      if (v != spec_values_.end()) return v->second;
    }
    switch (c.op) {
      case kOpConstant: case kOpSpecConstant: return c.args.at(0);
      case kOpConstantTrue: case kOpSpecConstantTrue: return 1;
      case kOpConstantFalse: case kOpSpecConstantFalse: return 0;
      default: throw std::runtime_error("a SPIR-V array size or work-group size that is not a scalar constant");
    }
  }

  // Bytes of a type: block members at their offsets, arrays at their stride; shared variables
  // (no layout decorations) packed at their scalar sizes, booleans as 4 bytes.
  uint32_t size_of(uint32_t type, uint32_t matrix_stride = 0) const {
    const Inst& t = m_.def(type);
    switch (t.op) {
      case kOpTypeBool: return 4;
      case kOpTypeInt: case kOpTypeFloat: return t.args.at(0) / 8;
      case kOpTypeVector: return t.args.at(1) * size_of(t.args.at(0));
      case kOpTypeMatrix: return t.args.at(1) * (matrix_stride ? matrix_stride : size_of(t.args.at(0)));
      case kOpTypeArray: {
        const auto stride = m_.array_strides.find(type);
        return value_of(t.args.at(1)) * (stride != m_.array_strides.end() ? stride->second : size_of(t.args.at(0)));
      }
      case kOpTypeRuntimeArray: return 0;
      case kOpTypeStruct: return struct_size(type, t);
      default: throw std::runtime_error("a SPIR-V type whose size is not known here");
    }
  }

 private:
  uint32_t operation_value(const Inst& c) const {
    const uint32_t opcode = c.args.at(0);
    if (opcode == kOpCompositeExtract) return value_of(m_.def(c.args.at(1)).args.at(c.args.at(2)));
    const uint32_t x = value_of(c.args.at(1)), y = value_of(c.args.at(2));
    switch (opcode) {
      case kOpIAdd: return x + y;
      case kOpISub: return x - y;
      case kOpIMul: return x * y;
      case kOpUDiv:
      case kOpSDiv:
        if (y == 0) throw std::runtime_error("a SPIR-V spec-constant division by zero");
        return x / y;
      case kOpShiftLeftLogical: return x << y;
      case kOpShiftRightLogical: return x >> y;
      default: throw std::runtime_error("a SPIR-V spec-constant operation not known here: " + std::to_string(opcode));
    }
  }

  // The end of its last-ending member; members without an Offset are packed after each other.
  uint32_t struct_size(uint32_t type, const Inst& t) const {
    uint32_t end = 0, packed = 0;
    for (uint32_t member = 0; member < t.args.size(); ++member) {
      const uint32_t size =
          size_of(t.args[member], DecodedModule::member_value(m_.matrix_strides, type, member).value_or(0));
      end = std::max(end, DecodedModule::member_value(m_.member_offsets, type, member).value_or(packed) + size);
      packed += size;
    }
    return end;
  }

  const DecodedModule& m_;
  const std::map<uint32_t, uint32_t>& spec_values_;
};

bool is_resource(uint32_t storage) {
  return storage == kStorageClassUniformConstant || storage == kStorageClassUniform ||
         storage == kStorageClassStorageBuffer;
}

// The descriptor type of a resource variable of storage class `storage` whose (element) type is `type`.
VkDescriptorType descriptor_type(const DecodedModule& m, uint32_t storage, uint32_t type) {
  const auto has = [](const std::map<uint32_t, bool>& decorated, uint32_t id) {
    const auto it = decorated.find(id);
    return it != decorated.end() && it->second;
  };
  if (storage == kStorageClassStorageBuffer || (storage == kStorageClassUniform && has(m.buffer_block, type)))
    return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  if (storage == kStorageClassUniform && has(m.block, type)) return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  const Inst& t = m.def(type);
  if (t.op == kOpTypeSampler) return VK_DESCRIPTOR_TYPE_SAMPLER;
  if (t.op == kOpTypeSampledImage) return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  if (t.op == kOpTypeImage) {
    // OpTypeImage operands: sampled type, Dim, Depth, Arrayed, MS, Sampled (1 sampled, 2 storage).
    const bool storage_image = t.args.at(5) == 2, buffer = t.args.at(1) == kDimBuffer;
    return buffer ? (storage_image ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER : VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER)
                  : (storage_image ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE);
  }
  throw std::runtime_error("a SPIR-V resource variable of a kind not known here");
}

ReflectedDescriptor reflect_descriptor(const DecodedModule& m, const SpecializedModule& s, const Variable& v) {
  ReflectedDescriptor d;
  const auto decoration = [&](const std::map<uint32_t, uint32_t>& table) {
    const auto it = table.find(v.id);
    return it == table.end() ? 0u : it->second;
  };
  d.set = decoration(m.sets);
  d.binding = decoration(m.bindings);
  uint32_t type = m.def(v.pointer_type).args.at(1);
  if (m.def(type).op == kOpTypeArray) {
    d.count = s.value_of(m.def(type).args.at(1));
    type = m.def(type).args.at(0);
  } else if (m.def(type).op == kOpTypeRuntimeArray) {
    throw std::runtime_error("a runtime-sized descriptor array (descriptor indexing is not used here)");
  }
  d.type = descriptor_type(m, v.storage, type);
  return d;
}

// The work-group size, and the spec id each component takes (from the constant decorated
// WorkgroupSize, else the LocalSize execution mode: literal sizes).
void reflect_workgroup_size(const DecodedModule& m, const SpecializedModule& s, KernelInterface& out) {
  if (m.workgroup_builtin) {
    const Inst& c = m.def(*m.workgroup_builtin);
    for (std::size_t k = 0; k < 3; ++k) {
      const uint32_t component = c.args.at(k);
      out.workgroup_size[k] = s.value_of(component);
      const auto spec = m.spec_ids.find(component);
      if (c.op == kOpSpecConstantComposite && spec != m.spec_ids.end()) out.workgroup_size_spec_ids[k] = spec->second;
    }
  } else if (m.local_size.size() == 3) {
    for (std::size_t k = 0; k < 3; ++k) out.workgroup_size[k] = m.local_size[k];
  }
}

}  // namespace

KernelInterface reflect_kernel(std::span<const uint32_t> words, const std::map<uint32_t, uint32_t>& spec_values) {
  const DecodedModule m = decode_module(words);
  const SpecializedModule s(m, spec_values);
  KernelInterface out;
  out.compute = m.compute;
  for (const Variable& v : m.vars) {
    const uint32_t pointee = m.def(v.pointer_type).args.at(1);
    if (v.storage == kStorageClassPushConstant)
      out.push_constant_bytes = std::max(out.push_constant_bytes, s.size_of(pointee));
    else if (v.storage == kStorageClassWorkgroup) out.shared_memory_bytes += s.size_of(pointee);
    else if (is_resource(v.storage)) out.descriptors.push_back(reflect_descriptor(m, s, v));
  }
  reflect_workgroup_size(m, s, out);
  std::sort(out.descriptors.begin(), out.descriptors.end(), [](const auto& x, const auto& y) {
    return x.set != y.set ? x.set < y.set : x.binding < y.binding;
  });
  return out;
}

}  // namespace vsgl
