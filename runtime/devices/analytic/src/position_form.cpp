// The analytic model's one assumption about a vertex listing's position: the quad corners
// reach oPos unchanged, so the quad covers the target exactly and the texcoord input is
// the quad uv at every pixel (pixel_uv).
#include <fmt/format.h>

#include "linear_forms.h"
#include "tierlift/ir/opcodes.h"
#include "tierlift/ir/sm3_interface.h"

namespace tierlift::analytic {

ir::Status check_position_passthrough(const ir::Program& listing) {
  // A vs_3_0 writes its position to the o# declared dcl_position: seen as oPos here.
  const ir::Program vs = ir::link_by_semantic(listing);
  uint32_t position = 0; // D3D8-style listings without declarations feed v0
  for (const ir::Declaration& d : vs.decls)
    if (d.reg.file == ir::RegFile::Input && d.usage == ir::DeclUsage::Position) {
      position = d.reg.index;
      break;
    }
  const ir::Instruction* last = nullptr; // the last write to oPos decides
  for (const ir::Instruction& in : vs.code) {
    const ir::OpInfo& info = ir::op_info(in.op);
    if (info.cls == ir::OpClass::Flow && in.op != ir::Opcode::Label)
      return detail::form_failure(
          fmt::format("{}: flow control ({}) is outside the model of the full-screen quad",
                      detail::where(in.loc), info.mnemonic));
    if (in.dst && in.dst->file == ir::RegFile::RastOut && in.dst->index == ir::kRastPos) last = &in;
  }
  if (!last) return detail::form_failure("oPos is never written");
  const bool passthrough =
      last->op == ir::Opcode::Mov && last->dst->mask == ir::kFullMask && !last->mods.sat &&
      last->mods.shift == 0 && last->src.size() == 1 && last->src[0].file == ir::RegFile::Input &&
      last->src[0].index == position && !last->src[0].rel &&
      last->src[0].swizzle == ir::kIdentitySwizzle && last->src[0].mod == ir::SrcMod::None;
  if (!passthrough)
    return detail::form_failure(
        fmt::format("{}: oPos is not the position input v{} passed through (mov oPos, v{})",
                    detail::where(last->loc), position, position));
  return ir::ok_status();
}

} // namespace tierlift::analytic
