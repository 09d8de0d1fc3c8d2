// Internal: what a listing reads that the caller must supply (constants, sampler stages,
// the position input). Read off the IR, first occurrence of each register with its position.
#pragma once

#include <vector>

#include "tierlift/ir/program.h"

namespace tierlift::pass::detail {

struct RegRead {
  ir::RegFile file;
  uint32_t index;
  ir::SourceLoc loc;
};

// c#, i#, b# read directly (matrix macros count their rows). Relative reads c[a0.x + n]
// come back separately in `relative`, since their registers are known only at run time.
std::vector<RegRead> constant_reads(const ir::Program& program, std::vector<RegRead>* relative);
// Sampler stages the program samples: s# of ps_2_0 texld* (and of vs_3_0 texldl, the vertex
// stage's own samplers), the stage of ps_1_x texture instructions that sample (tex, texld,
// texbem, texm3x3tex, ...). Stages as RegFile::Sampler.
std::vector<RegRead> sampler_reads(const ir::Program& program);

} // namespace tierlift::pass::detail
