// RGBA8 UNORM → RGBA32F on the device through a table of k/255.0f (unorm8_to_float.h).
#include "unorm8_to_float.h"

#include <cstring>
#include <initializer_list>

#include <spirv/unified1/spirv.hpp11>

namespace tierlift::vulkan {
namespace {

constexpr uint32_t kLocalSize = 8;

// One instruction: word count and opcode, then the operands.
void ins(std::vector<uint32_t>& w, spv::Op op, std::initializer_list<uint32_t> operands) {
  w.push_back(static_cast<uint32_t>(operands.size() + 1) << 16 | static_cast<uint32_t>(op));
  w.insert(w.end(), operands.begin(), operands.end());
}
template <typename E> constexpr uint32_t u(E e) {
  return static_cast<uint32_t>(e);
}

} // namespace

std::vector<uint32_t> unorm8_to_float_spirv() {
  // The GLSL it corresponds to:
  //   layout(local_size_x = 8, local_size_y = 8) in;
  //   layout(set = 0, binding = 0) readonly buffer In { uint texels[]; };
  //   layout(set = 0, binding = 1) readonly buffer Table { float table[]; };
  //   layout(set = 0, binding = 2) writeonly buffer Out { vec4 dst[]; };
  //   layout(push_constant) uniform Size { uint width, height; };
  //   void main() {
  //     uvec3 id = gl_GlobalInvocationID;
  //     if (id.x < width && id.y < height) {
  //       uint t = texels[id.y * width + id.x];          // R in the low byte
  //       dst[id.y * width + id.x] = vec4(table[t & 255], table[(t >> 8) & 255],
  //                                         table[(t >> 16) & 255], table[t >> 24]);
  //     }
  //   }
  // Result ids, in order of definition.
  // clang-format off
  enum : uint32_t {
    kVoid = 1, kFn, kBool, kUint, kFloat, kV3Uint, kV4Float,                          // types
    kRtUint, kIn, kRtFloat, kTable, kRtV4, kOut, kSize,                               // blocks
    kPtrIn, kPtrTable, kPtrOut, kPtrSize, kPtrGid, kPtrSbUint, kPtrSbFloat, kPtrSbV4, kPtrPcUint,
    kC0, kC1, kC8, kC16, kC24, kC255,                                                 // constants
    kGid, kSrc, kTab, kDst, kSizeVar,                                                 // variables
    kMain, kEntry, kBody, kEnd,                                                       // function
    kId, kX, kY, kPw, kW, kPh, kH, kInX, kInY, kInside,                               // code
    kRow, kI, kPt, kT, kR, kG0, kG, kB0, kB, kA,
    kPr, kFr, kPg, kFg, kPb, kFb, kPa, kFa, kV, kPd,
    kBound
  };
  // clang-format on
  std::vector<uint32_t> w = {spv::MagicNumber, 0x00010300, 0, kBound, 0};
  using spv::Op;
  ins(w, Op::OpCapability, {u(spv::Capability::Shader)});
  ins(w, Op::OpMemoryModel, {u(spv::AddressingModel::Logical), u(spv::MemoryModel::GLSL450)});
  // "main" as a nul-terminated little-endian string: two words.
  ins(w, Op::OpEntryPoint, {u(spv::ExecutionModel::GLCompute), kMain, 0x6e69616du, 0u, kGid});
  ins(w, Op::OpExecutionMode, {kMain, u(spv::ExecutionMode::LocalSize), kLocalSize, kLocalSize, 1});

  const uint32_t set = u(spv::Decoration::DescriptorSet), binding = u(spv::Decoration::Binding);
  const uint32_t offset = u(spv::Decoration::Offset), block = u(spv::Decoration::Block);
  ins(w, Op::OpDecorate, {kGid, u(spv::Decoration::BuiltIn), u(spv::BuiltIn::GlobalInvocationId)});
  ins(w, Op::OpDecorate, {kRtUint, u(spv::Decoration::ArrayStride), 4});
  ins(w, Op::OpMemberDecorate, {kIn, 0, offset, 0});
  ins(w, Op::OpDecorate, {kIn, block});
  ins(w, Op::OpDecorate, {kRtFloat, u(spv::Decoration::ArrayStride), 4});
  ins(w, Op::OpMemberDecorate, {kTable, 0, offset, 0});
  ins(w, Op::OpDecorate, {kTable, block});
  ins(w, Op::OpDecorate, {kRtV4, u(spv::Decoration::ArrayStride), 16});
  ins(w, Op::OpMemberDecorate, {kOut, 0, offset, 0});
  ins(w, Op::OpDecorate, {kOut, block});
  ins(w, Op::OpMemberDecorate, {kSize, 0, offset, 0});
  ins(w, Op::OpMemberDecorate, {kSize, 1, offset, 4});
  ins(w, Op::OpDecorate, {kSize, block});
  ins(w, Op::OpDecorate, {kSrc, u(spv::Decoration::NonWritable)});
  ins(w, Op::OpDecorate, {kTab, u(spv::Decoration::NonWritable)});
  for (auto [var, b] : {std::pair{kSrc, 0u}, {kTab, 1u}, {kDst, 2u}}) {
    ins(w, Op::OpDecorate, {var, set, 0});
    ins(w, Op::OpDecorate, {var, binding, b});
  }

  ins(w, Op::OpTypeVoid, {kVoid});
  ins(w, Op::OpTypeFunction, {kFn, kVoid});
  ins(w, Op::OpTypeBool, {kBool});
  ins(w, Op::OpTypeInt, {kUint, 32, 0});
  ins(w, Op::OpTypeFloat, {kFloat, 32});
  ins(w, Op::OpTypeVector, {kV3Uint, kUint, 3});
  ins(w, Op::OpTypeVector, {kV4Float, kFloat, 4});
  ins(w, Op::OpTypeRuntimeArray, {kRtUint, kUint});
  ins(w, Op::OpTypeStruct, {kIn, kRtUint});
  ins(w, Op::OpTypeRuntimeArray, {kRtFloat, kFloat});
  ins(w, Op::OpTypeStruct, {kTable, kRtFloat});
  ins(w, Op::OpTypeRuntimeArray, {kRtV4, kV4Float});
  ins(w, Op::OpTypeStruct, {kOut, kRtV4});
  ins(w, Op::OpTypeStruct, {kSize, kUint, kUint});
  const uint32_t sb = u(spv::StorageClass::StorageBuffer);
  const uint32_t pc = u(spv::StorageClass::PushConstant);
  ins(w, Op::OpTypePointer, {kPtrIn, sb, kIn});
  ins(w, Op::OpTypePointer, {kPtrTable, sb, kTable});
  ins(w, Op::OpTypePointer, {kPtrOut, sb, kOut});
  ins(w, Op::OpTypePointer, {kPtrSize, pc, kSize});
  ins(w, Op::OpTypePointer, {kPtrGid, u(spv::StorageClass::Input), kV3Uint});
  ins(w, Op::OpTypePointer, {kPtrSbUint, sb, kUint});
  ins(w, Op::OpTypePointer, {kPtrSbFloat, sb, kFloat});
  ins(w, Op::OpTypePointer, {kPtrSbV4, sb, kV4Float});
  ins(w, Op::OpTypePointer, {kPtrPcUint, pc, kUint});
  for (auto [id, v] :
       {std::pair{kC0, 0u}, {kC1, 1u}, {kC8, 8u}, {kC16, 16u}, {kC24, 24u}, {kC255, 255u}})
    ins(w, Op::OpConstant, {kUint, id, v});
  ins(w, Op::OpVariable, {kPtrGid, kGid, u(spv::StorageClass::Input)});
  ins(w, Op::OpVariable, {kPtrIn, kSrc, sb});
  ins(w, Op::OpVariable, {kPtrTable, kTab, sb});
  ins(w, Op::OpVariable, {kPtrOut, kDst, sb});
  ins(w, Op::OpVariable, {kPtrSize, kSizeVar, pc});

  ins(w, Op::OpFunction, {kVoid, kMain, u(spv::FunctionControlMask::MaskNone), kFn});
  ins(w, Op::OpLabel, {kEntry});
  ins(w, Op::OpLoad, {kV3Uint, kId, kGid});
  ins(w, Op::OpCompositeExtract, {kUint, kX, kId, 0});
  ins(w, Op::OpCompositeExtract, {kUint, kY, kId, 1});
  ins(w, Op::OpAccessChain, {kPtrPcUint, kPw, kSizeVar, kC0});
  ins(w, Op::OpLoad, {kUint, kW, kPw});
  ins(w, Op::OpAccessChain, {kPtrPcUint, kPh, kSizeVar, kC1});
  ins(w, Op::OpLoad, {kUint, kH, kPh});
  ins(w, Op::OpULessThan, {kBool, kInX, kX, kW});
  ins(w, Op::OpULessThan, {kBool, kInY, kY, kH});
  ins(w, Op::OpLogicalAnd, {kBool, kInside, kInX, kInY});
  ins(w, Op::OpSelectionMerge, {kEnd, u(spv::SelectionControlMask::MaskNone)});
  ins(w, Op::OpBranchConditional, {kInside, kBody, kEnd});

  ins(w, Op::OpLabel, {kBody});
  ins(w, Op::OpIMul, {kUint, kRow, kY, kW});
  ins(w, Op::OpIAdd, {kUint, kI, kRow, kX});
  ins(w, Op::OpAccessChain, {kPtrSbUint, kPt, kSrc, kC0, kI});
  ins(w, Op::OpLoad, {kUint, kT, kPt});
  ins(w, Op::OpBitwiseAnd, {kUint, kR, kT, kC255});
  ins(w, Op::OpShiftRightLogical, {kUint, kG0, kT, kC8});
  ins(w, Op::OpBitwiseAnd, {kUint, kG, kG0, kC255});
  ins(w, Op::OpShiftRightLogical, {kUint, kB0, kT, kC16});
  ins(w, Op::OpBitwiseAnd, {kUint, kB, kB0, kC255});
  ins(w, Op::OpShiftRightLogical, {kUint, kA, kT, kC24});
  for (auto [ptr, val, byte] :
       {std::tuple{kPr, kFr, kR}, {kPg, kFg, kG}, {kPb, kFb, kB}, {kPa, kFa, kA}}) {
    ins(w, Op::OpAccessChain, {kPtrSbFloat, ptr, kTab, kC0, byte});
    ins(w, Op::OpLoad, {kFloat, val, ptr});
  }
  ins(w, Op::OpCompositeConstruct, {kV4Float, kV, kFr, kFg, kFb, kFa});
  ins(w, Op::OpAccessChain, {kPtrSbV4, kPd, kDst, kC0, kI});
  ins(w, Op::OpStore, {kPd, kV});
  ins(w, Op::OpBranch, {kEnd});
  ins(w, Op::OpLabel, {kEnd});
  ins(w, Op::OpReturn, {});
  ins(w, Op::OpFunctionEnd, {});
  return w;
}

std::string ensure_unorm8_converter(Device::Impl& d) {
  if (d.unorm8) return {};
  auto c = std::make_unique<Unorm8Converter>();
  VkDevice dev = d.device;
  VkResult r;
  std::string err = create_buffer(d, c->objects, 256 * sizeof(float),
                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, c->table);
  if (!err.empty()) return err;
  auto* table = static_cast<float*>(c->table.mapped);
  for (uint32_t k = 0; k < 256; ++k) table[k] = static_cast<float>(k) / 255.0f; // correctly rounded

  const VkDescriptorSetLayoutBinding bindings[3] = {
      {0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
      {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
      {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}};
  VkDescriptorSetLayoutCreateInfo dli{};
  dli.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  dli.bindingCount = 3;
  dli.pBindings = bindings;
  if ((r = vkCreateDescriptorSetLayout(dev, &dli, nullptr, &c->set_layout)) != VK_SUCCESS)
    return vk_error("vkCreateDescriptorSetLayout", r);
  VkDescriptorSetLayout dsl = c->set_layout;
  c->objects.add([dev, dsl] { vkDestroyDescriptorSetLayout(dev, dsl, nullptr); });
  const VkPushConstantRange size_range{VK_SHADER_STAGE_COMPUTE_BIT, 0, 8};
  VkPipelineLayoutCreateInfo pli{};
  pli.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  pli.setLayoutCount = 1;
  pli.pSetLayouts = &dsl;
  pli.pushConstantRangeCount = 1;
  pli.pPushConstantRanges = &size_range;
  if ((r = vkCreatePipelineLayout(dev, &pli, nullptr, &c->layout)) != VK_SUCCESS)
    return vk_error("vkCreatePipelineLayout", r);
  VkPipelineLayout layout = c->layout;
  c->objects.add([dev, layout] { vkDestroyPipelineLayout(dev, layout, nullptr); });

  const std::vector<uint32_t> words = unorm8_to_float_spirv();
  VkShaderModuleCreateInfo smi{};
  smi.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  smi.codeSize = words.size() * sizeof(uint32_t);
  smi.pCode = words.data();
  VkShaderModule module = VK_NULL_HANDLE;
  if ((r = vkCreateShaderModule(dev, &smi, nullptr, &module)) != VK_SUCCESS)
    return vk_error("vkCreateShaderModule", r);
  VkComputePipelineCreateInfo cpi{};
  cpi.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
  cpi.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  cpi.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  cpi.stage.module = module;
  cpi.stage.pName = "main";
  cpi.layout = layout;
  r = vkCreateComputePipelines(dev, VK_NULL_HANDLE, 1, &cpi, nullptr, &c->pipeline);
  vkDestroyShaderModule(dev, module, nullptr); // the pipeline keeps what it needs
  if (r != VK_SUCCESS) return vk_error("vkCreateComputePipelines", r);
  VkPipeline pipeline = c->pipeline;
  c->objects.add([dev, pipeline] { vkDestroyPipeline(dev, pipeline, nullptr); });
  d.unorm8 = std::move(c);
  return {};
}

std::string create_unorm8_scratch(Device::Impl& d, Cleanup& cleanup, uint32_t width,
                                  uint32_t height, Unorm8Scratch& out) {
  if (std::string err = ensure_unorm8_converter(d); !err.empty()) return err;
  const VkDeviceSize texels = VkDeviceSize{width} * height;
  std::string err = create_buffer(
      d, cleanup, texels * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
      out.bytes);
  if (err.empty())
    err = create_buffer(d, cleanup, texels * 16,
                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                        out.floats);
  if (!err.empty()) return err;
  VkDevice dev = d.device;
  const VkDescriptorPoolSize sizes[1] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3}};
  VkDescriptorPoolCreateInfo dpi{};
  dpi.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  dpi.maxSets = 1;
  dpi.poolSizeCount = 1;
  dpi.pPoolSizes = sizes;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkResult r = vkCreateDescriptorPool(dev, &dpi, nullptr, &pool);
  if (r != VK_SUCCESS) return vk_error("vkCreateDescriptorPool", r);
  cleanup.add([dev, pool] { vkDestroyDescriptorPool(dev, pool, nullptr); });
  VkDescriptorSetAllocateInfo dsa{};
  dsa.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  dsa.descriptorPool = pool;
  dsa.descriptorSetCount = 1;
  dsa.pSetLayouts = &d.unorm8->set_layout;
  if ((r = vkAllocateDescriptorSets(dev, &dsa, &out.set)) != VK_SUCCESS)
    return vk_error("vkAllocateDescriptorSets", r);
  const VkDescriptorBufferInfo infos[3] = {{out.bytes.buffer, 0, VK_WHOLE_SIZE},
                                           {d.unorm8->table.buffer, 0, VK_WHOLE_SIZE},
                                           {out.floats.buffer, 0, VK_WHOLE_SIZE}};
  VkWriteDescriptorSet writes[3]{};
  for (uint32_t k = 0; k < 3; ++k) {
    writes[k].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    writes[k].dstSet = out.set;
    writes[k].dstBinding = k;
    writes[k].descriptorCount = 1;
    writes[k].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[k].pBufferInfo = &infos[k];
  }
  vkUpdateDescriptorSets(dev, 3, writes, 0, nullptr);
  return {};
}

void record_unorm8_to_float(VkCommandBuffer cb, const Device::Impl& d, const Unorm8Scratch& s,
                            VkImage stored, VkImage shadow, uint32_t width, uint32_t height) {
  auto buffer_barrier = [](VkBuffer b, VkAccessFlags src, VkAccessFlags dst) {
    VkBufferMemoryBarrier bb{};
    bb.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER;
    bb.srcQueueFamilyIndex = bb.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    bb.buffer = b;
    bb.size = VK_WHOLE_SIZE;
    bb.srcAccessMask = src;
    bb.dstAccessMask = dst;
    return bb;
  };
  // The previous conversion's reads of both buffers finish before they are written again.
  const VkBufferMemoryBarrier reuse[2] = {
      buffer_barrier(s.bytes.buffer, 0, VK_ACCESS_TRANSFER_WRITE_BIT),
      buffer_barrier(s.floats.buffer, 0, VK_ACCESS_SHADER_WRITE_BIT)};
  vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                       nullptr, 2, reuse, 0, nullptr);
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = {width, height, 1};
  vkCmdCopyImageToBuffer(cb, stored, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, s.bytes.buffer, 1,
                         &copy);
  const VkBufferMemoryBarrier texels =
      buffer_barrier(s.bytes.buffer, VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT);
  vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0,
                       0, nullptr, 1, &texels, 0, nullptr);
  vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, d.unorm8->pipeline);
  vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, d.unorm8->layout, 0, 1, &s.set, 0,
                          nullptr);
  const uint32_t size[2] = {width, height};
  vkCmdPushConstants(cb, d.unorm8->layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(size), size);
  vkCmdDispatch(cb, (width + kLocalSize - 1) / kLocalSize, (height + kLocalSize - 1) / kLocalSize,
                1);
  const VkBufferMemoryBarrier floats =
      buffer_barrier(s.floats.buffer, VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT);
  vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                       0, nullptr, 1, &floats, 0, nullptr);
  vkCmdCopyBufferToImage(cb, s.floats.buffer, shadow, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                         &copy);
}

} // namespace tierlift::vulkan
