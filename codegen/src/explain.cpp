// --explain: what link-time pruning left out, one readable line per item.
#include "tierlift/codegen/codegen.h"

namespace tierlift::codegen {

std::string explain(const std::vector<PrunedItem>& pruned) {
  std::string out;
  for (const PrunedItem& p : pruned) {
    const char* stage = p.stage == ir::ShaderStage::Vertex ? "vertex" : "pixel";
    const char* kind = "";
    switch (p.kind) {
    case PrunedItem::Kind::VertexOutput: kind = "output"; break;
    case PrunedItem::Kind::VertexInput:
    case PrunedItem::Kind::PixelInput: kind = "input"; break;
    case PrunedItem::Kind::Constant: kind = "constant"; break;
    case PrunedItem::Kind::DeadInstruction: kind = "instruction"; break;
    }
    out += std::string(stage) + ": removed " + kind + " " + p.what + ": " + p.reason;
    if (p.loc.valid()) out += " (line " + std::to_string(p.loc.line) + ")";
    out += '\n';
  }
  return out;
}

} // namespace tierlift::codegen
