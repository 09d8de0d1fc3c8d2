// The interpreter run that decides NUMERICS.md rule 38: the pixel program at the pass's
// constant inputs, its texture reads watched by a TextureUnit that forwards every read to the
// device's own sampler and notes the first whose coordinate is not finite.
#include "tierlift/corpus/undefined_reads.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "tierlift/cpu/shader_vm.h"
#include "tierlift/cpu/texture.h"
#include "tierlift/ir/profile.h"

namespace tierlift::corpus {
namespace {

// How many coordinate components stage s addresses: xyz for a cube or volume declared in a
// ps_2_0 program, xy otherwise (2D, and the ps_1_x stages the run binds 2D textures to).
int addressed_components(const ir::Program& p, uint32_t stage) {
  for (const ir::Declaration& d : p.decls)
    if (d.reg.file == ir::RegFile::Sampler && d.reg.index == stage &&
        (d.sampler_type == ir::SamplerType::Cube || d.sampler_type == ir::SamplerType::Volume))
      return 3;
  return 2;
}

// Whether stage s is declared dcl_cube (ps_2_0 and later).
bool is_cube(const ir::Program& p, uint32_t stage) {
  for (const ir::Declaration& d : p.decls)
    if (d.reg.file == ir::RegFile::Sampler && d.reg.index == stage &&
        d.sampler_type == ir::SamplerType::Cube)
      return true;
  return false;
}

// A coordinate component as the message shows it: NaN without its sign bit's "-".
std::string show(float v) {
  return std::isnan(v) ? "nan" : fmt::format("{}", v);
}

class WatchedTextures final : public cpu::TextureUnit {
public:
  WatchedTextures(const cpu::TextureUnit& inner, const ir::Program& program)
      : inner_(inner), program_(program) {}
  cpu::Vec4 sample(uint32_t stage, const cpu::Vec4& coord, float lod_bias) const override {
    if (first_.empty()) {
      const int n = addressed_components(program_, stage);
      bool finite = true;
      for (int c = 0; c < n; ++c) finite = finite && std::isfinite(coord[c]);
      // A cube read in direction (0, 0, 0) has no major axis (its face coordinates are 0/0):
      // Direct3D 9 leaves it undefined as well (NUMERICS.md rule 38).
      const bool zero_direction =
          is_cube(program_, stage) && coord[0] == 0 && coord[1] == 0 && coord[2] == 0;
      if (!finite || zero_direction)
        first_ = n == 3 ? fmt::format("s{} at ({}, {}, {})", stage, show(coord[0]), show(coord[1]),
                                      show(coord[2]))
                        : fmt::format("s{} at ({}, {})", stage, show(coord[0]), show(coord[1]));
    }
    return inner_.sample(stage, coord, lod_bias);
  }
  cpu::StageState stage_state(uint32_t stage) const override { return inner_.stage_state(stage); }
  const std::string& first() const { return first_; }

private:
  const cpu::TextureUnit& inner_;
  const ir::Program& program_;
  mutable std::string first_;
};

// A vertex program's reads (vs_3_0 texldl): the program at each of the pass's vertices.
std::string non_finite_vertex_read(const pass::Pass& pass) {
  ir::Result<cpu::ShaderVM> vm = cpu::ShaderVM::create(*pass.vertex_program, pass.conventions);
  if (!vm) return "";
  const cpu::BoundTextures bound(pass.vertex_textures, pass.conventions.subtexel_bits,
                                 pass.conventions.rounding == ir::Rounding::Llvmpipe);
  const WatchedTextures watched(bound, *pass.vertex_program);
  for (const pass::VertexInput& v : pass.vertices) {
    vm->run_vertex(v, pass.vs_constants, watched);
    if (!watched.first().empty()) return "vertex " + watched.first();
  }
  return "";
}

} // namespace

std::string non_finite_read(const pass::Pass& pass) {
  if (pass.vertex_program && !pass.pixel_program && pass.transformed.empty())
    return non_finite_vertex_read(pass);
  if (!pass.pixel_program || pass.vertex_program || !pass.transformed.empty()) return "";
  ir::Result<cpu::ShaderVM> vm = cpu::ShaderVM::create(*pass.pixel_program, pass.conventions);
  if (!vm) return "";
  pass::PixelInput in = pass.constant_inputs;
  for (auto& colour : in.color) // as the draw feeds them (NUMERICS.md rule 26)
    for (float& v : colour) v = v > 0 ? (v < 1 ? v : 1) : 0;
  const cpu::BoundTextures bound(pass.textures, pass.conventions.subtexel_bits,
                                 pass.conventions.rounding == ir::Rounding::Llvmpipe);
  const WatchedTextures watched(bound, *pass.pixel_program);
  vm->run_pixel(in, pass.ps_constants, watched);
  return watched.first();
}

namespace {

bool written_or_read(const ir::Program& p, ir::RegFile file, uint32_t index) {
  for (const ir::Instruction& ins : p.code) {
    if (ins.dst && ins.dst->file == file && ins.dst->index == index) return true;
    for (const ir::SrcOperand& s : ins.src)
      if (s.file == file && s.index == index) return true;
  }
  return false;
}

// A temporary the program never names, from the top; nullopt when all are used.
std::optional<uint32_t> spare_temp(const ir::Program& p, uint32_t below) {
  for (uint32_t r = ir::limits(p.profile).temps; r-- > 0;)
    if (r < below && !written_or_read(p, ir::RegFile::Temp, r)) return r;
  return std::nullopt;
}

ir::DstOperand dst_x(ir::RegFile file, uint32_t index) {
  return ir::DstOperand{file, index, 0x1, {}};
}
ir::SrcOperand temp_x(uint32_t index) {
  ir::SrcOperand s;
  s.file = ir::RegFile::Temp;
  s.index = index;
  s.swizzle = 0x00; // .xxxx
  return s;
}

// sincos in either form: two constants (2.0, 2.x) or one source (3.0, Opcode::SinCos3).
bool is_sincos(const ir::Instruction& ins) {
  return (ins.op == ir::Opcode::SinCos || ins.op == ir::Opcode::SinCos3) && !ins.src.empty();
}

// Where a vertex program's probe leaves its value: oT7. A vs_3_0 writes only declared o#, so
// its copy declares a spare o# as texcoord7, which links to oT7 (ir/sm3_interface.h); nullopt
// when it declares texcoord7 itself or uses every o#.
std::optional<ir::DstOperand> vertex_probe_output(ir::Program& p) {
  if (p.profile != ir::Profile::vs_3_0) return dst_x(ir::RegFile::TexCrdOut, 7);
  std::optional<uint32_t> spare;
  for (uint32_t o = ir::limits(p.profile).tex_outputs; o-- > 0;) {
    bool used = written_or_read(p, ir::RegFile::Output, o);
    for (const ir::Declaration& d : p.decls) {
      if (d.reg.file != ir::RegFile::Output) continue;
      if (d.usage == ir::DeclUsage::TexCoord && d.usage_index == 7) return std::nullopt;
      used |= d.reg.index == o;
    }
    if (!used) {
      spare = o;
      break;
    }
  }
  if (!spare) return std::nullopt;
  ir::Declaration d;
  d.reg = dst_x(ir::RegFile::Output, *spare);
  d.reg.mask = ir::kFullMask;
  d.usage = ir::DeclUsage::TexCoord;
  d.usage_index = 7;
  p.decls.push_back(d);
  return dst_x(ir::RegFile::Output, *spare);
}

// The copy: before each sincos (subroutines too), |its argument| (the fourth swizzle slot, as
// sincos reads a scalar) into rT.x and max(rA.x, rT.x) into rA.x (temporaries start at 0 in
// the VM); where the main program ends, rA.x into `out`.
std::optional<ir::Program> sincos_probe(const ir::Program& p, ir::DstOperand out) {
  bool any = false;
  for (const ir::Instruction& ins : p.code) any |= is_sincos(ins);
  if (!any || written_or_read(p, out.file, out.index)) return std::nullopt;
  const std::optional<uint32_t> acc = spare_temp(p, 256);
  const std::optional<uint32_t> arg = acc ? spare_temp(p, *acc) : std::nullopt;
  if (!acc || !arg) return std::nullopt;
  // Where the main program ends: its `ret` before the first subroutine label, else the end.
  size_t main_end = p.code.size();
  for (size_t i = 0; i < p.code.size() && p.code[i].op != ir::Opcode::Label; ++i)
    if (p.code[i].op == ir::Opcode::Ret) {
      main_end = i;
      break;
    }
  ir::Instruction mov;
  mov.op = ir::Opcode::Mov;
  mov.dst = out;
  mov.src.push_back(temp_x(*acc));
  ir::Program q = p;
  q.code.clear();
  uint32_t last_seq = 0;
  for (size_t i = 0; i < p.code.size(); ++i) {
    const ir::Instruction& ins = p.code[i];
    if (i == main_end) {
      mov.seq = ins.seq;
      q.code.push_back(mov);
    }
    last_seq = std::max(last_seq, ins.seq);
    if (is_sincos(ins)) {
      ir::Instruction a;
      a.op = ir::Opcode::Abs;
      a.dst = dst_x(ir::RegFile::Temp, *arg);
      ir::SrcOperand x = ins.src[0];
      x.swizzle = static_cast<uint8_t>(((x.swizzle >> 6) & 3) * 0x55);
      a.src.push_back(x);
      a.seq = ins.seq;
      ir::Instruction m;
      m.op = ir::Opcode::Max;
      m.dst = dst_x(ir::RegFile::Temp, *acc);
      m.src = {temp_x(*acc), temp_x(*arg)};
      m.seq = ins.seq;
      q.code.push_back(std::move(a));
      q.code.push_back(std::move(m));
    }
    q.code.push_back(ins);
  }
  if (main_end == p.code.size()) {
    mov.seq = last_seq + 1;
    q.code.push_back(std::move(mov));
  }
  return q;
}

} // namespace

std::string sincos_out_of_range(const pass::Pass& pass) {
  const bool pixel = pass.pixel_program && !pass.vertex_program && pass.transformed.empty();
  const bool vertex = pass.vertex_program && !pass.pixel_program;
  if (!pixel && !vertex) return "";
  ir::Program p = pixel ? *pass.pixel_program : *pass.vertex_program;
  const std::optional<ir::DstOperand> out =
      pixel ? dst_x(ir::RegFile::ColorOut, 3) : vertex_probe_output(p);
  const std::optional<ir::Program> probe = out ? sincos_probe(p, *out) : std::nullopt;
  if (!probe) return "";
  ir::Result<cpu::ShaderVM> vm = cpu::ShaderVM::create(*probe, pass.conventions);
  if (!vm) return "";
  std::vector<float> largest;
  if (pixel) {
    pass::PixelInput in = pass.constant_inputs;
    for (auto& colour : in.color)
      for (float& v : colour) v = v > 0 ? (v < 1 ? v : 1) : 0;
    const cpu::BoundTextures bound(pass.textures, pass.conventions.subtexel_bits,
                                   pass.conventions.rounding == ir::Rounding::Llvmpipe);
    largest.push_back(vm->run_pixel(in, pass.ps_constants, bound).color[3][0]);
  } else {
    for (const pass::VertexInput& v : pass.vertices)
      largest.push_back(vm->run_vertex(v, pass.vs_constants).tex[7][0]);
  }
  constexpr float kPi = 3.14159274f; // fl32(π): the bound an fp32 argument can meet
  for (float a : largest)
    if (!(a <= kPi)) return "sincos of " + show(a);
  return "";
}

} // namespace tierlift::corpus
