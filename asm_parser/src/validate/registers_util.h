// Which register files a profile has, how many registers each holds, and which are
// read-only or write-only (docs/d3d9-rules.md §2–§3, counts from ir::limits()).
#pragma once

#include "context.h"

namespace tierlift::as::detail {

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
  case RegFile::RastOut: return c.vs() ? 3 : 0;
  case RegFile::AttrOut: return c.vs() ? l.color_outputs : 0;
  case RegFile::TexCrdOut: return c.vs() ? l.tex_outputs : 0;
  case RegFile::ConstInt: return l.int_consts;
  case RegFile::ColorOut: return c.ps20() ? l.color_outputs : 0;
  case RegFile::DepthOut: return c.ps20() ? 1 : 0;
  case RegFile::Sampler: return c.ps20() ? l.samplers : 0;
  case RegFile::ConstBool: return l.bool_consts;
  case RegFile::Loop: return c.vs20() ? 1 : 0;
  case RegFile::Label: return l.labels;
  }
  return 0;
}

inline bool is_output(ir::RegFile f) {
  using ir::RegFile;
  return f == RegFile::RastOut || f == RegFile::AttrOut || f == RegFile::TexCrdOut ||
         f == RegFile::ColorOut || f == RegFile::DepthOut;
}

// Files an instruction may write. t# is writable only in ps_1_1–1_3 (texture results and
// arithmetic); in ps_1_4 and ps_2_0 it holds read-only coordinates.
inline bool writable(const Ctx& c, ir::RegFile f) {
  using ir::RegFile;
  if (f == RegFile::Texture) return c.ps11_13();
  return f == RegFile::Temp || f == RegFile::Addr || is_output(f);
}

} // namespace tierlift::as::detail
