// Pass (analysis): which constants relative addressing can reach.
#include <algorithm>

#include "tierlift/ir/passes.h"

namespace tierlift::ir {

uint32_t relative_constant_limit(Profile p) {
  const uint32_t limit = limits(p).float_consts;
  return is_vertex(p) ? std::max<uint32_t>(limit, 256) : limit;
}

std::optional<RelativeReach> relative_reach(const Program& program) {
  for (const Instruction& ins : program.code)
    for (const SrcOperand& s : ins.src)
      if (s.rel && s.file == RegFile::Const)
        return RelativeReach{0, relative_constant_limit(program.profile)};
  return std::nullopt;
}

} // namespace tierlift::ir
