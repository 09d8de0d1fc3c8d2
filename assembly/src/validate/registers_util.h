// Which register files a profile has, how many registers each holds, and which are
// read-only or write-only (docs/d3d9-rules.md §2–§3, counts from ir::limits()).
#pragma once

#include "context.h"

namespace tierlift::assembly::detail {

// Registers in file f in the target; 0 when the file does not exist there.
inline uint32_t file_count(const Ctx& c, ir::RegFile f) {
  using ir::RegFile;
  const ir::ProfileLimits& l = c.lim;
  switch (f) {
  case RegFile::Temp: return l.temps;
  case RegFile::Input: return l.inputs;
  case RegFile::Const: return l.float_consts;
  case RegFile::Addr: return c.vs() ? 1 : 0;
  case RegFile::Texture: return c.vs() ? 0 : l.texcoords;
  // vs_3_0 has declared outputs o# in place of oPos, oFog, oPts, oD# and oT#.
  case RegFile::RastOut: return c.vs() && !c.vs30() ? 3 : 0;
  case RegFile::AttrOut: return c.vs() && !c.vs30() ? l.color_outputs : 0;
  case RegFile::TexCrdOut: return c.vs() && !c.vs30() ? l.tex_outputs : 0;
  case RegFile::ConstInt: return l.int_consts;
  case RegFile::ColorOut: return c.ps2up() ? l.color_outputs : 0;
  case RegFile::DepthOut: return c.ps2up() ? 1 : 0;
  case RegFile::Sampler: return (c.ps2up() || c.vs30()) ? l.samplers : 0;
  case RegFile::ConstBool: return l.bool_consts;
  case RegFile::Loop: return (c.vs2up() || c.ps30()) ? 1 : 0;
  case RegFile::Label: return l.labels;
  case RegFile::Output: return c.vs30() ? l.tex_outputs : 0;
  case RegFile::Predicate: return c.caps.predication ? 1 : 0;
  case RegFile::Misc: return c.ps30() ? 2 : 0;
  }
  return 0;
}

inline bool is_output(ir::RegFile f) {
  using ir::RegFile;
  return f == RegFile::RastOut || f == RegFile::AttrOut || f == RegFile::TexCrdOut ||
         f == RegFile::ColorOut || f == RegFile::DepthOut || f == RegFile::Output;
}

// Files an instruction may write. t# is writable only in ps_1_1–1_3 (texture results and
// arithmetic); in ps_1_4 and ps_2_0 it holds read-only coordinates.
inline bool writable(const Ctx& c, ir::RegFile f) {
  using ir::RegFile;
  if (f == RegFile::Texture) return c.ps11_13();
  // p0 is written by setp only (rules_later.cpp says so for any other writer).
  return f == RegFile::Temp || f == RegFile::Addr || f == RegFile::Predicate || is_output(f);
}

} // namespace tierlift::assembly::detail
