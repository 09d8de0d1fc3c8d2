// RGBA8 UNORM → RGBA32F on the device, k/255.0f computed exactly (unorm8_to_float.h).
#include "unorm8_to_float.h"

#include <spirv/unified1/spirv.hpp11>

#include "tierlift/codegen/spirv_builder.h"

namespace tierlift::vulkan {
namespace {

constexpr uint32_t kLocalSize = 8;

} // namespace

std::vector<uint32_t> unorm8_to_float_spirv() {
  // The GLSL it corresponds to:
  //   layout(local_size_x = 8, local_size_y = 8) in;
  //   layout(set = 0, binding = 0) readonly buffer In { uint texels[]; };
  //   layout(set = 0, binding = 1) writeonly buffer Out { vec4 dst[]; };
  //   layout(push_constant) uniform Size { uint width, height; };
  //   void main() {
  //     uvec3 id = gl_GlobalInvocationID;
  //     if (id.x < width && id.y < height) {
  //       uint t = texels[id.y * width + id.x];          // R in the low byte
  //       dst[id.y * width + id.x] = vec4(level(t & 255), level((t >> 8) & 255),
  //                                         level((t >> 16) & 255), level(t >> 24));
  //     }
  //   }
  //   precise float level(uint k) {
  //     float f = float(k);
  //     return (f * 65793.0 + f * (1.0 / 255.0)) * 0x1p-24;
  //   }
  using spv::Decoration;
  using spv::Op;
  using SC = spv::StorageClass;
  codegen::SpirvBuilder b;
  b.capability(spv::Capability::Shader);
  b.memory_model(spv::AddressingModel::Logical, spv::MemoryModel::GLSL450);

  const codegen::Id t_void = b.type_void(), t_bool = b.type_bool(), t_uint = b.type_int(false),
                    t_float = b.type_float();
  const codegen::Id t_v3uint = b.type_vector(t_uint, 3), t_v4float = b.type_vector(t_float, 4);
  // One storage block per binding: a struct holding a runtime array of `element`.
  auto storage_block = [&](codegen::Id element, uint32_t stride, uint32_t binding, bool readonly) {
    const codegen::Id array = b.type_runtime_array(element);
    b.decorate(array, Decoration::ArrayStride, stride);
    const codegen::Id members[] = {array};
    const codegen::Id block = b.type_struct(members);
    b.member_decorate(block, 0, Decoration::Offset, 0u);
    b.decorate(block, Decoration::Block);
    const codegen::Id var =
        b.global_variable(b.type_pointer(SC::StorageBuffer, block), SC::StorageBuffer);
    if (readonly) b.decorate(var, Decoration::NonWritable);
    b.decorate(var, Decoration::DescriptorSet, 0u);
    b.decorate(var, Decoration::Binding, binding);
    return var;
  };
  const codegen::Id src = storage_block(t_uint, 4, 0, true);
  const codegen::Id dst = storage_block(t_v4float, 16, 1, false);
  const codegen::Id size_members[] = {t_uint, t_uint};
  const codegen::Id size_block = b.type_struct(size_members);
  b.member_decorate(size_block, 0, Decoration::Offset, 0u);
  b.member_decorate(size_block, 1, Decoration::Offset, 4u);
  b.decorate(size_block, Decoration::Block);
  const codegen::Id size =
      b.global_variable(b.type_pointer(SC::PushConstant, size_block), SC::PushConstant);
  const codegen::Id gid = b.global_variable(b.type_pointer(SC::Input, t_v3uint), SC::Input);
  b.decorate(gid, Decoration::BuiltIn, static_cast<uint32_t>(spv::BuiltIn::GlobalInvocationId));
  const codegen::Id c0 = b.const_uint(0), c1 = b.const_uint(1), c255 = b.const_uint(255);

  const codegen::Id main = b.begin_function(t_void, b.type_function(t_void));
  const codegen::Id interface[] = {gid};
  b.entry_point(spv::ExecutionModel::GLCompute, main, "main", interface);
  const uint32_t local_size[] = {kLocalSize, kLocalSize, 1};
  b.execution_mode(main, spv::ExecutionMode::LocalSize, local_size);
  const codegen::Id body = b.fresh_id(), end = b.fresh_id();
  b.begin_block(b.fresh_id());
  const codegen::Id id = b.op(Op::OpLoad, t_v3uint, {gid});
  const codegen::Id x = b.op(Op::OpCompositeExtract, t_uint, {id, 0});
  const codegen::Id y = b.op(Op::OpCompositeExtract, t_uint, {id, 1});
  const codegen::Id ptr_pc_uint = b.type_pointer(SC::PushConstant, t_uint);
  const codegen::Id w =
      b.op(Op::OpLoad, t_uint, {b.op(Op::OpAccessChain, ptr_pc_uint, {size, c0})});
  const codegen::Id h =
      b.op(Op::OpLoad, t_uint, {b.op(Op::OpAccessChain, ptr_pc_uint, {size, c1})});
  const codegen::Id inside =
      b.op(Op::OpLogicalAnd, t_bool,
           {b.op(Op::OpULessThan, t_bool, {x, w}), b.op(Op::OpULessThan, t_bool, {y, h})});
  b.op_void(Op::OpSelectionMerge,
            {end, static_cast<uint32_t>(spv::SelectionControlMask::MaskNone)});
  b.op_void(Op::OpBranchConditional, {inside, body, end});

  b.begin_block(body);
  const codegen::Id i = b.op(Op::OpIAdd, t_uint, {b.op(Op::OpIMul, t_uint, {y, w}), x});
  const codegen::Id t =
      b.op(Op::OpLoad, t_uint,
           {b.op(Op::OpAccessChain, b.type_pointer(SC::StorageBuffer, t_uint), {src, c0, i})});
  // k/255.0f from the byte k, exactly: k/255 = (k·65793 + k/255)·2^-24 (2^24/255 = 65793 +
  // 1/255). k·65793 < 2^24 is exact; fl(k·fl(1/255)) is within an ulp (2^-24) of k/255,
  // while k·65793 + k/255 lies at least 1/(255·2^8) of the sum's ulp from a rounding midpoint
  // (k/255 repeats an 8-bit pattern), so the sum rounds as the exact one does; 2^-24 scales
  // exactly. Every level is checked (Rgba8SamplesExactlyKOver255).
  const codegen::Id f65793 = b.const_float(65793.0f), finv = b.const_float(1.0f / 255.0f),
                    fscale = b.const_float(0x1p-24f);
  auto op = [&](Op o, codegen::Id x, codegen::Id y) {
    const codegen::Id r = b.op(o, t_float, {x, y});
    b.decorate(r, Decoration::NoContraction);
    return r;
  };
  codegen::Id rgba[4];
  for (uint32_t c = 0; c < 4; ++c) {
    // Byte c of the texel: (t >> 8c) & 255 (the top byte needs no mask).
    codegen::Id byte = c == 0 ? t : b.op(Op::OpShiftRightLogical, t_uint, {t, b.const_uint(8 * c)});
    if (c < 3) byte = b.op(Op::OpBitwiseAnd, t_uint, {byte, c255});
    const codegen::Id k = b.op(Op::OpConvertUToF, t_float, {byte});
    const codegen::Id sum = op(Op::OpFAdd, op(Op::OpFMul, k, f65793), op(Op::OpFMul, k, finv));
    rgba[c] = op(Op::OpFMul, sum, fscale);
  }
  const codegen::Id v =
      b.op(Op::OpCompositeConstruct, t_v4float, {rgba[0], rgba[1], rgba[2], rgba[3]});
  const codegen::Id pd =
      b.op(Op::OpAccessChain, b.type_pointer(SC::StorageBuffer, t_v4float), {dst, c0, i});
  b.op_void(Op::OpStore, {pd, v});
  b.op_void(Op::OpBranch, {end});

  b.begin_block(end);
  b.op_void(Op::OpReturn, {});
  b.end_function();
  return b.finish();
}

ir::Status ensure_unorm8_converter(Device::Impl& d) {
  if (d.unorm8) return ir::ok_status();
  auto c = std::make_unique<Unorm8Converter>();
  VkDevice dev = d.device;
  VkResult r;
  const VkDescriptorSetLayoutBinding bindings[2] = {
      {0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
      {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}};
  VkDescriptorSetLayoutCreateInfo dli{};
  dli.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  dli.bindingCount = 2;
  dli.pBindings = bindings;
  if ((r = vkCreateDescriptorSetLayout(dev, &dli, nullptr, &c->set_layout)) != VK_SUCCESS)
    return draw_failure(vk_error("vkCreateDescriptorSetLayout", r));
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
    return draw_failure(vk_error("vkCreatePipelineLayout", r));
  VkPipelineLayout layout = c->layout;
  c->objects.add([dev, layout] { vkDestroyPipelineLayout(dev, layout, nullptr); });

  const std::vector<uint32_t> words = unorm8_to_float_spirv();
  VkShaderModuleCreateInfo smi{};
  smi.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  smi.codeSize = words.size() * sizeof(uint32_t);
  smi.pCode = words.data();
  VkShaderModule module = VK_NULL_HANDLE;
  if ((r = vkCreateShaderModule(dev, &smi, nullptr, &module)) != VK_SUCCESS)
    return draw_failure(vk_error("vkCreateShaderModule", r));
  VkComputePipelineCreateInfo cpi{};
  cpi.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
  cpi.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  cpi.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  cpi.stage.module = module;
  cpi.stage.pName = "main";
  cpi.layout = layout;
  r = vkCreateComputePipelines(dev, VK_NULL_HANDLE, 1, &cpi, nullptr, &c->pipeline);
  vkDestroyShaderModule(dev, module, nullptr); // the pipeline keeps what it needs
  if (r != VK_SUCCESS) return draw_failure(vk_error("vkCreateComputePipelines", r));
  VkPipeline pipeline = c->pipeline;
  c->objects.add([dev, pipeline] { vkDestroyPipeline(dev, pipeline, nullptr); });
  d.unorm8 = std::move(c);
  return ir::ok_status();
}

ir::Status create_unorm8_scratch(Device::Impl& d, Cleanup& cleanup, uint32_t width, uint32_t height,
                                 Unorm8Scratch& out) {
  if (ir::Status err = ensure_unorm8_converter(d); !err) return err;
  const VkDeviceSize texels = VkDeviceSize{width} * height;
  ir::Status err = create_buffer(
      d, cleanup, texels * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
      out.bytes);
  if (err)
    err = create_buffer(d, cleanup, texels * 16,
                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                        out.floats);
  if (!err) return err;
  VkDevice dev = d.device;
  const VkDescriptorPoolSize sizes[1] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2}};
  VkDescriptorPoolCreateInfo dpi{};
  dpi.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  dpi.maxSets = 1;
  dpi.poolSizeCount = 1;
  dpi.pPoolSizes = sizes;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkResult r = vkCreateDescriptorPool(dev, &dpi, nullptr, &pool);
  if (r != VK_SUCCESS) return draw_failure(vk_error("vkCreateDescriptorPool", r));
  cleanup.destroy_later(dev, pool, vkDestroyDescriptorPool);
  VkDescriptorSetAllocateInfo dsa{};
  dsa.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  dsa.descriptorPool = pool;
  dsa.descriptorSetCount = 1;
  dsa.pSetLayouts = &d.unorm8->set_layout;
  if ((r = vkAllocateDescriptorSets(dev, &dsa, &out.set)) != VK_SUCCESS)
    return draw_failure(vk_error("vkAllocateDescriptorSets", r));
  const VkDescriptorBufferInfo infos[2] = {{out.bytes.buffer, 0, VK_WHOLE_SIZE},
                                           {out.floats.buffer, 0, VK_WHOLE_SIZE}};
  VkWriteDescriptorSet writes[2]{};
  for (uint32_t k = 0; k < 2; ++k) {
    writes[k].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    writes[k].dstSet = out.set;
    writes[k].dstBinding = k;
    writes[k].descriptorCount = 1;
    writes[k].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[k].pBufferInfo = &infos[k];
  }
  vkUpdateDescriptorSets(dev, 2, writes, 0, nullptr);
  return ir::ok_status();
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
