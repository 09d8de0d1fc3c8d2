// The public face of the VM: builds the prepared program once and runs it per vertex or
// per pixel with all state on the caller's stack (thread-safe, no heap per invocation).
#include <algorithm>

#include "tierlift/ir/numerics.h"
#include "tierlift/ir/profile.h"
#include "vm_internal.h"

namespace tierlift::cpu {

struct ShaderVM::Impl {
  vm::Prepared p;
};

ShaderVM::ShaderVM(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

ir::Result<ShaderVM> ShaderVM::create(const ir::Program& program,
                                      const ir::Conventions& conventions) {
  ir::Result<vm::Prepared> prepared = vm::prepare(program, conventions);
  if (!prepared) return std::move(prepared).failure();
  return ShaderVM(std::make_unique<Impl>(Impl{std::move(*prepared)}));
}

ShaderVM::~ShaderVM() = default;
ShaderVM::ShaderVM(ShaderVM&&) noexcept = default;
ShaderVM& ShaderVM::operator=(ShaderVM&&) noexcept = default;

const ir::Program& ShaderVM::program() const {
  return impl_->p.program;
}

namespace {

void begin(vm::Invocation& inv, const vm::Prepared& p, const ConstantBank& constants) {
  std::fill(std::begin(inv.reg), std::end(inv.reg), Vec4{0, 0, 0, 0});
  inv.prog = &p;
  inv.consts = &constants;
}

} // namespace

VertexOutput ShaderVM::run_vertex(const VertexInput& in, const ConstantBank& constants) const {
  return vertex(in, constants, nullptr);
}

VertexOutput ShaderVM::run_vertex(const VertexInput& in, const ConstantBank& constants,
                                  const TextureUnit& textures) const {
  return vertex(in, constants, &textures);
}

// One vertex. Its texldl reads `textures` (nullptr: (0, 0, 0, 1)) at the lod it gives: a
// vertex has no neighbours, so no read of this stage takes gradients.
VertexOutput ShaderVM::vertex(const VertexInput& in, const ConstantBank& constants,
                              const TextureUnit* textures) const {
  const vm::Prepared& p = impl_->p;
  vm::Invocation inv;
  begin(inv, p, constants);
  inv.tex = textures;
  for (int i = 0; i < vm::kInputCount; ++i) inv.reg[vm::kInputBase + i] = in.v[i];
  inv.reg[vm::kOutBase + vm::kOutPos] = {0, 0, 0, 1};
  vm::run(p, inv);

  VertexOutput out;
  const Vec4* o = inv.reg + vm::kOutBase;
  out.pos = o[vm::kOutPos];
  out.fog = o[vm::kOutFog][p.fog_component];
  out.point_size = o[vm::kOutPts][p.pts_component];
  for (int i = 0; i < 2; ++i) out.color[i] = o[vm::kOutD0 + i];
  for (int i = 0; i < 8; ++i) out.tex[i] = o[vm::kOutT0 + i];
  out.color_written = static_cast<uint8_t>((inv.out_written >> vm::kOutD0) & 0x3);
  out.tex_written = static_cast<uint8_t>((inv.out_written >> vm::kOutT0) & 0xFF);
  return out;
}

namespace {

void begin_pixel(vm::Invocation& inv, const vm::Prepared& p, const PixelInput& in,
                 const ConstantBank& constants, const TextureUnit& textures, PixelOutput& out) {
  begin(inv, p, constants);
  inv.tex = &textures;
  inv.pin = &in;
  inv.pout = &out;
  // Colour inputs lie in [0, 1] in every pixel profile before ps_3_0 (docs/d3d9-rules.md
  // §3.3, §3.5); a ps_3_0 reads them as they come, like texture coordinates (NUMERICS.md F6).
  namespace num = ir::numerics;
  for (int i = 0; i < 2; ++i)
    for (int c = 0; c < 4; ++c)
      inv.reg[vm::kInputBase + i][c] = !p.saturate_colors ? in.color[i][c]
                                       : p.flush ? num::legacy_saturate<num::kFlush>(in.color[i][c])
                                                 : num::legacy_saturate(in.color[i][c]);
  // ps_1_4 and ps_2_0 read t# as the interpolated coordinates; in ps_1_1–1_3 t# are
  // registers that texture instructions fill.
  if (!p.ps11_13)
    for (int i = 0; i < vm::kTexCount; ++i) inv.reg[vm::kTexBase + i] = in.tex[i];
  // ps_3_0 vPos (z = w = 0) and vFace (all four components).
  inv.reg[vm::kMiscBase + ir::kMiscPosition] = {in.pos_x, in.pos_y, 0.0f, 0.0f};
  inv.reg[vm::kMiscBase + ir::kMiscFace] = {in.face, in.face, in.face, in.face};
}

void end_pixel(const vm::Invocation& inv, const vm::Prepared& p, PixelOutput& out) {
  const Vec4* o = inv.reg + vm::kOutBase;
  if (p.ps1x) {
    out.color[0] = inv.reg[vm::kTempBase]; // r0 is the colour
    out.color_written = 1;
  } else {
    for (int i = 0; i < 4; ++i) out.color[i] = o[vm::kOutC0 + i];
    out.color_written = static_cast<uint8_t>(inv.out_written & 0xF);
    if (inv.out_written & (1u << vm::kOutDepth)) out.depth = o[vm::kOutDepth][0];
  }
}

PixelOutput pixel(const vm::Prepared& p, const PixelInput& in, const ConstantBank& constants,
                  const TextureUnit& textures, InstructionTrace* trace) {
  vm::Invocation inv;
  PixelOutput out;
  begin_pixel(inv, p, in, constants, textures, out);
  if (trace)
    vm::run_traced(p, inv, *trace);
  else
    vm::run(p, inv);
  end_pixel(inv, p, out);
  return out;
}

} // namespace

PixelOutput ShaderVM::run_pixel(const PixelInput& in, const ConstantBank& constants,
                                const TextureUnit& textures) const {
  return pixel(impl_->p, in, constants, textures, nullptr);
}

PixelOutput ShaderVM::run_pixel(const PixelInput& in, const ConstantBank& constants,
                                const TextureUnit& textures, InstructionTrace& trace) const {
  return pixel(impl_->p, in, constants, textures, &trace);
}

bool ShaderVM::needs_quad() const {
  const auto& steps = impl_->p.steps;
  return std::any_of(steps.begin(), steps.end(), [](const vm::Step& s) { return s.gradient; });
}

void ShaderVM::enable_lod_quads() {
  if (!ir::is_sm2_or_later(impl_->p.program.profile) ||
      impl_->p.program.stage() != ir::ShaderStage::Pixel)
    return;
  for (vm::Step& s : impl_->p.steps) {
    const ir::Opcode op = s.ins ? s.ins->op : ir::Opcode::Nop;
    if (op == ir::Opcode::TexLd || op == ir::Opcode::TexLdP || op == ir::Opcode::TexLdB)
      s.gradient = true;
  }
}

namespace {

void quad(const vm::Prepared& p, const std::array<PixelInput, 4>& in, const ConstantBank& constants,
          const TextureUnit& textures, std::array<PixelOutput, 4>& out, InstructionTrace* trace,
          int traced) {
  vm::Invocation inv[4];
  for (size_t l = 0; l < 4; ++l) {
    out[l] = PixelOutput{};
    begin_pixel(inv[l], p, in[l], constants, textures, out[l]);
  }
  vm::run_quad(p, {&inv[0], &inv[1], &inv[2], &inv[3]}, trace, traced);
  for (size_t l = 0; l < 4; ++l) end_pixel(inv[l], p, out[l]);
}

} // namespace

void ShaderVM::run_quad(const std::array<PixelInput, 4>& in, const ConstantBank& constants,
                        const TextureUnit& textures, std::array<PixelOutput, 4>& out) const {
  quad(impl_->p, in, constants, textures, out, nullptr, 0);
}

void ShaderVM::run_quad(const std::array<PixelInput, 4>& in, const ConstantBank& constants,
                        const TextureUnit& textures, std::array<PixelOutput, 4>& out,
                        InstructionTrace& trace, int traced) const {
  quad(impl_->p, in, constants, textures, out, &trace, traced);
}

} // namespace tierlift::cpu
