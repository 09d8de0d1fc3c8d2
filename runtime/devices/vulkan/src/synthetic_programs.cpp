#include "synthetic_programs.h"

namespace tierlift::vulkan {
namespace {

ir::Instruction mov(ir::RegFile dst_file, uint32_t dst_index, ir::RegFile src_file,
                    uint32_t src_index) {
  ir::Instruction ins;
  ins.op = ir::Opcode::Mov;
  ins.dst = ir::DstOperand{dst_file, dst_index, ir::kFullMask, {}};
  ir::SrcOperand s;
  s.file = src_file;
  s.index = src_index;
  ins.src.push_back(s);
  return ins;
}

ir::Declaration input_decl(uint32_t index, ir::DeclUsage usage, uint8_t usage_index) {
  ir::Declaration d;
  d.reg = ir::DstOperand{ir::RegFile::Input, index, ir::kFullMask, {}};
  d.usage = usage;
  d.usage_index = usage_index;
  return d;
}

} // namespace

std::shared_ptr<const ir::Program> passthrough_vertex_program() {
  auto p = std::make_shared<ir::Program>();
  p->profile = ir::Profile::vs_2_0;
  p->decls.push_back(input_decl(kPassPosition, ir::DeclUsage::Position, 0));
  for (uint8_t n = 0; n < 2; ++n)
    p->decls.push_back(input_decl(kPassColor + n, ir::DeclUsage::Color, n));
  for (uint8_t n = 0; n < 8; ++n)
    p->decls.push_back(input_decl(kPassTex + n, ir::DeclUsage::TexCoord, n));
  p->code.push_back(mov(ir::RegFile::RastOut, ir::kRastPos, ir::RegFile::Input, kPassPosition));
  for (uint32_t n = 0; n < 2; ++n)
    p->code.push_back(mov(ir::RegFile::AttrOut, n, ir::RegFile::Input, kPassColor + n));
  for (uint32_t n = 0; n < 8; ++n)
    p->code.push_back(mov(ir::RegFile::TexCrdOut, n, ir::RegFile::Input, kPassTex + n));
  uint32_t seq = 0;
  for (auto& d : p->decls) d.seq = seq++;
  for (auto& c : p->code) c.seq = seq++;
  return p;
}

std::shared_ptr<const ir::Program> passthrough_pixel_program() {
  auto p = std::make_shared<ir::Program>();
  p->profile = ir::Profile::ps_2_0;
  ir::Declaration d;
  d.reg = ir::DstOperand{ir::RegFile::Input, 0, ir::kFullMask, {}};
  d.seq = 0;
  p->decls.push_back(d);
  p->code.push_back(mov(ir::RegFile::ColorOut, 0, ir::RegFile::Input, 0));
  p->code.back().seq = 1;
  return p;
}

std::shared_ptr<const ir::Program> texel_copy_pixel_program() {
  auto p = std::make_shared<ir::Program>();
  p->profile = ir::Profile::ps_2_0;
  ir::Declaration t0;
  t0.reg = ir::DstOperand{ir::RegFile::Texture, 0, ir::kFullMask, {}};
  ir::Declaration s0;
  s0.reg = ir::DstOperand{ir::RegFile::Sampler, 0, ir::kFullMask, {}};
  s0.sampler_type = ir::SamplerType::Tex2D;
  p->decls = {t0, s0};
  ir::Instruction tex = mov(ir::RegFile::Temp, 0, ir::RegFile::Texture, 0);
  tex.op = ir::Opcode::TexLd;
  ir::SrcOperand sampler;
  sampler.file = ir::RegFile::Sampler;
  tex.src.push_back(sampler);
  p->code = {tex, mov(ir::RegFile::ColorOut, 0, ir::RegFile::Temp, 0)};
  uint32_t seq = 0;
  for (auto& d : p->decls) d.seq = seq++;
  for (auto& c : p->code) c.seq = seq++;
  return p;
}

pass::Pass texel_copy_pass(uint32_t width, uint32_t height) {
  pass::Pass p;
  p.vertex_program = passthrough_vertex_program();
  p.pixel_program = texel_copy_pixel_program();
  pass::set_full_screen_quad(p, kPassPosition);
  for (size_t c = 0; c < p.vertices.size(); ++c) {
    pass::Vec4 uv = pass::kQuadUV[c];
    uv[0] += 0.5f / float(width);
    uv[1] += 0.5f / float(height);
    p.vertices[c].v[kPassTex] = uv;
  }
  pass::SamplerState& s = p.textures[0].sampler;
  s.filter = pass::Filter::Point;
  s.address_u = s.address_v = pass::AddressMode::Clamp;
  return p;
}

} // namespace tierlift::vulkan
