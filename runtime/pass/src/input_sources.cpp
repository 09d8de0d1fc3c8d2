// What drives each input of a run, and the quad-uv vertex stage (input_sources.h).
#include "tierlift/pass/input_sources.h"

#include <fmt/format.h>
#include <tuple>

#include "tierlift/ir/sm3_interface.h"

namespace tierlift::pass {
namespace {

// Bit n set: register n of `file` is declared or named by an instruction (source or
// destination: ps_1_x's `tex t0` names the coordinate set it reads as its destination).
// A ps_3_0's v# count by their semantic (dcl_texcoord2 v0 names t2), as the devices read them.
uint16_t registers_named(const ir::Program& listing, ir::RegFile file, uint32_t limit) {
  const ir::Program program = ir::link_by_semantic(listing);
  uint16_t mask = 0;
  auto add = [&](ir::RegFile f, uint32_t index) {
    if (f == file && index < limit) mask |= static_cast<uint16_t>(1u << index);
  };
  for (const ir::Declaration& d : program.decls) add(d.reg.file, d.reg.index);
  for (const ir::Instruction& ins : program.code) {
    if (ins.dst) add(ins.dst->file, ins.dst->index);
    for (const ir::SrcOperand& op : ins.src)
      if (!op.rel) add(op.file, op.index); // v[aL + n] reaches declared registers only
  }
  return mask;
}

const RegisterSetting* find_setting(const std::vector<RegisterSetting>& list, ir::RegFile file,
                                    uint32_t index) {
  const RegisterSetting* found = nullptr;
  for (const RegisterSetting& s : list) // the last one given wins, as prepare_pass applies them
    if (s.file == file && s.index == index) found = &s;
  return found;
}

std::string vec_text(const Vec4& v) {
  return fmt::format("{:g},{:g},{:g},{:g}", v[0], v[1], v[2], v[3]);
}

// The t# of the pixel listing that --input leaves to the quad uv (bit n: tn).
uint8_t uv_mask(const RunRequest& r) {
  if (r.vs || !r.ps || !r.texcoords_from_quad) return 0;
  const uint16_t named = registers_named(*r.ps, ir::RegFile::Texture, 8);
  uint8_t mask = 0;
  for (uint32_t t = 0; t < 8; ++t)
    if (((named >> t) & 1) && !find_setting(r.inputs, ir::RegFile::Texture, t))
      mask |= static_cast<uint8_t>(1u << t);
  return mask;
}

std::vector<InputSource> pixel_sources(const RunRequest& r) {
  std::vector<InputSource> out;
  const uint8_t uv = uv_mask(r);
  for (auto [file, count, name] :
       {std::tuple{ir::RegFile::Input, 2u, 'v'}, std::tuple{ir::RegFile::Texture, 8u, 't'}}) {
    const uint16_t named = r.ps ? registers_named(*r.ps, file, count) : uint16_t(0);
    for (uint32_t n = 0; n < count; ++n) {
      if (!((named >> n) & 1)) continue;
      const std::string reg = fmt::format("{}{}", name, n);
      std::string source;
      if (const RegisterSetting* s = find_setting(r.inputs, file, n))
        source = fmt::format("{} everywhere (--input {}={})", vec_text(s->value), reg,
                             vec_text(s->value));
      else if ((uv >> n) & 1)
        source = "quad uv (no --vs)";
      else
        source = fmt::format("0 everywhere (no --vs; --input {}=x,y,z,w sets it)", reg);
      out.push_back({reg, std::move(source)});
    }
  }
  return out;
}

std::vector<InputSource> vertex_sources(const RunRequest& r) {
  std::vector<InputSource> out;
  const uint32_t position = position_input(*r.vs);
  const uint16_t named = registers_named(*r.vs, ir::RegFile::Input, 16);
  for (uint32_t n = 0; n < 16; ++n) {
    if (!((named >> n) & 1)) continue;
    const RegisterSetting* s = find_setting(r.attrs, ir::RegFile::Input, n);
    std::string source;
    if (n == position)
      source = "quad corners (position)";
    else if (s && s->quad_uv)
      source = fmt::format("quad uv (--attr v{}=quad-uv)", n);
    else if (s)
      source = fmt::format("--attr v{}={}", n, vec_text(s->value));
    else
      source = fmt::format("0,0,0,1 (not given; --attr v{}=quad-uv or x,y,z,w sets it)", n);
    out.push_back({fmt::format("v{}", n), std::move(source)});
  }
  return out;
}

ir::DstOperand reg(ir::RegFile file, uint32_t index) {
  ir::DstOperand d;
  d.file = file;
  d.index = index;
  return d;
}

ir::SrcOperand src(ir::RegFile file, uint32_t index) {
  ir::SrcOperand s;
  s.file = file;
  s.index = index;
  return s;
}

} // namespace

std::vector<InputSource> describe_inputs(const RunRequest& request) {
  return request.vs ? vertex_sources(request) : pixel_sources(request);
}

bool uses_quad_uv_stage(const RunRequest& request) {
  return uv_mask(request) != 0;
}

std::shared_ptr<const ir::Program> quad_uv_vertex_program(uint8_t uv) {
  auto p = std::make_shared<ir::Program>();
  p->profile = ir::Profile::vs_1_1;
  uint32_t seq = 0;
  for (auto [index, usage] :
       {std::pair{0u, ir::DeclUsage::Position}, std::pair{1u, ir::DeclUsage::TexCoord}}) {
    ir::Declaration d;
    d.reg = reg(ir::RegFile::Input, index);
    d.usage = usage;
    d.seq = seq++;
    p->decls.push_back(d);
  }
  auto mov = [&](ir::DstOperand dst, ir::SrcOperand from) {
    ir::Instruction ins;
    ins.op = ir::Opcode::Mov;
    ins.dst = dst;
    ins.src.push_back(from);
    ins.seq = seq++;
    p->code.push_back(std::move(ins));
  };
  mov(reg(ir::RegFile::RastOut, ir::kRastPos), src(ir::RegFile::Input, 0));
  for (uint32_t t = 0; t < 8; ++t)
    mov(reg(ir::RegFile::TexCrdOut, t),
        ((uv >> t) & 1) ? src(ir::RegFile::Input, 1) : src(ir::RegFile::Const, 2 + t));
  for (uint32_t c = 0; c < 2; ++c) mov(reg(ir::RegFile::AttrOut, c), src(ir::RegFile::Const, c));
  return p;
}

void set_quad_uv_stage(const RunRequest& request, Pass& pass) {
  pass.vertex_program = quad_uv_vertex_program(uv_mask(request));
  pass.vs_constants = ConstantBank{};
  pass.vs_constants.f.assign(10, Vec4{0, 0, 0, 0}); // c0, c1: oD0, oD1; c2..c9: oT0..oT7
  for (const RegisterSetting& in : request.inputs)
    pass.vs_constants.f[(in.file == ir::RegFile::Input ? 0 : 2) + in.index] = in.value;
  set_full_screen_quad_uv(pass);
}

} // namespace tierlift::pass
