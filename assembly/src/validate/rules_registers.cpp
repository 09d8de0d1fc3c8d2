// Register files and indices per profile (ir::limits), read-only / write-only files, read
// ports (distinct registers of one file per instruction; a co-issued pair counted
// together) and where relative addressing may appear.
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "context.h"
#include "registers_util.h"

namespace tierlift::assembly::detail {
namespace {

using ir::RegFile;

std::string range_text(RegFile f, uint32_t count) {
  if (count == 1) return reg_name(f, 0);
  if (f == RegFile::RastOut) return "oPos, oFog, oPts";
  return fmt::format("{}..{}", reg_name(f, 0), reg_name(f, count - 1));
}

// Vertex-shader c# counts are device caps (MaxVertexShaderConst) with a guaranteed minimum
// (96 in vs_1_1, 256 in vs_2_0). Indices past the minimum run on devices that report more
// (Irrlicht's shipping vs_1_1 shaders use c96), so they get a warning, once per register;
// past the bytecode's 8192 they are errors.
constexpr uint32_t kMaxVertexConsts = 8192;

void check_index(Ctx& c, RegFile f, uint32_t index, const ir::SourceLoc& loc) {
  uint32_t n = file_count(c, f);
  if (c.vs() && f == RegFile::Const && index >= n && index < kMaxVertexConsts) {
    if (c.warned_consts.insert(index).second)
      c.warning(loc, "register-range",
                fmt::format("{} is above the {} constants every {} device has "
                            "(MaxVertexShaderConst >= {}); it needs a device that reports more",
                            reg_name(f, index), n, c.pname(), n));
    return;
  }
  if (n == 0) {
    c.error(loc, "register-file",
            fmt::format("{} does not exist in {}", reg_name(f, index), c.pname()));
  } else if (index >= n) {
    c.error(loc, "register-range",
            fmt::format("{} is out of range: {} has {}", reg_name(f, index), c.pname(),
                        range_text(f, n)));
  }
}

// Which files may be addressed relatively: c# in vertex shaders; in vs_3_0 also v# (with
// aL) and the outputs o#; in ps_3_0 c# and v# with aL only.
bool relative_file_ok(const Ctx& c, RegFile f) {
  if (c.vs30()) return f == RegFile::Const || f == RegFile::Input || f == RegFile::Output;
  if (c.ps30()) return f == RegFile::Const || f == RegFile::Input;
  return c.vs() && f == RegFile::Const;
}

void check_relative(Ctx& c, RegFile file, uint32_t index, const std::optional<ir::RelAddr>& rel,
                    const ir::SourceLoc& loc) {
  if (!rel) return;
  if (!c.vs() && !c.ps30()) {
    c.error(loc, "relative-address",
            "relative addressing is only available in vertex shaders and ps_3_0");
    return;
  }
  if (!relative_file_ok(c, file)) {
    c.error(
        loc, "relative-address",
        fmt::format("{} cannot be addressed relatively in {}", reg_name(file, index), c.pname()));
    return;
  }
  const ir::SourceLoc at = rel->loc.valid() ? rel->loc : loc;
  if (!c.vs() && rel->file != RegFile::Loop)
    c.error(at, "relative-address", "ps_3_0 addresses registers with aL only (v[aL + n])");
  if (c.vs30() && file == RegFile::Input && rel->file != RegFile::Loop)
    c.error(at, "relative-address", "vs_3_0 addresses inputs with aL only (v[aL + n])");
}

void check_relative(Ctx& c, const ir::SrcOperand& s) {
  if (!s.rel) return;
  check_relative(c, s.file, s.index, s.rel, s.loc);
  if (!c.vs() || !relative_file_ok(c, s.file)) return;
  if (c.vs11() && (s.rel->file != RegFile::Addr || s.rel->component != 0))
    c.error(s.rel->loc.valid() ? s.rel->loc : s.loc, "relative-address",
            "vs_1_1 only allows c[a0.x + n] relative addressing");
  if (s.rel->file != RegFile::Addr && s.rel->file != RegFile::Loop)
    c.error(s.loc, "relative-address", "the relative index must be a0 or aL");
}

void check_access(Ctx& c, const ir::Instruction& ins) {
  if (ins.dst && ins.op != ir::Opcode::TexKill && !writable(c, ins.dst->file))
    c.error(ins.dst->loc, "register-access",
            fmt::format("{} is read-only in {}; it cannot be a destination",
                        reg_name(ins.dst->file, ins.dst->index), c.pname()));
  for (const ir::SrcOperand& s : ins.src) {
    if (is_output(s.file))
      c.error(s.loc, "register-access",
              fmt::format("{} is write-only; it cannot be read", reg_name(s.file, s.index)));
    else if (s.file == RegFile::Addr)
      c.error(s.loc, "register-access", "a0 can only be read as a relative index, c[a0.x + n]");
  }
  // ps_1_4: t# holds coordinates that only the texture unit reads (docs/d3d9-rules.md §3.4).
  if (c.ps14() && !is_texture_op(ins))
    for (const ir::SrcOperand& s : ins.src)
      if (s.file == RegFile::Texture)
        c.error(s.loc, "register-access",
                fmt::format("{} can only be read by texld, texcrd and texkill in ps_1_4",
                            reg_name(s.file, s.index)));
}

using Reads = std::vector<std::set<std::pair<uint32_t, bool>>>; // per file: (index, relative)

void collect(const ir::Instruction& ins, Reads& reads) {
  for (const ir::SrcOperand& s : ins.src) {
    size_t f = static_cast<size_t>(s.file);
    if (f < reads.size()) reads[f].insert({s.index, s.rel.has_value()});
  }
}

void check_ports(Ctx& c, const ir::Instruction& ins) {
  Reads reads(16);
  collect(ins, reads);
  // c# in vs_2_0/ps_2_0: the docs give "read ports 1, reads/inst 2" (docs/d3d9-rules.md §3.2,
  // unconfirmed). The literal reading (one distinct constant) would reject every
  // sincos, which must name two different constants in one instruction (§5.1), so the
  // "reads/inst 2" reading is taken: up to 2 distinct c# per instruction. vs_1_1 keeps its
  // well-known single constant; ps_1_x its 2.
  const int const_ports = c.lim.const_ports;
  const std::pair<RegFile, int> ports[] = {{RegFile::Temp, c.lim.temp_ports},
                                           {RegFile::Const, const_ports},
                                           {RegFile::Input, c.lim.input_ports},
                                           {RegFile::Texture, c.lim.texture_ports}};
  for (auto [f, limit] : ports) {
    size_t n = reads[static_cast<size_t>(f)].size();
    if (limit > 0 && n > static_cast<size_t>(limit)) {
      std::string names;
      for (auto [idx, rel] : reads[static_cast<size_t>(f)])
        names +=
            (names.empty() ? "" : ", ") + (rel ? fmt::format("c[a0 + {}]", idx) : reg_name(f, idx));
      c.error(ins.loc, "read-port",
              fmt::format("{} allows {} distinct {}# register{} per instruction (read ports); "
                          "this instruction reads {} ({})",
                          c.pname(), limit, reg_name(f, 0).substr(0, 1), limit == 1 ? "" : "s", n,
                          names));
    }
  }
}

// [DX8-SDK] Registers: across the two halves of a pair, at most 3 distinct registers of one
// type may be read.
void check_pair_ports(Ctx& c, const ir::Instruction& first, const ir::Instruction& second) {
  Reads reads(16);
  collect(first, reads);
  collect(second, reads);
  for (RegFile f : {RegFile::Temp, RegFile::Const, RegFile::Input, RegFile::Texture}) {
    size_t n = reads[static_cast<size_t>(f)].size();
    if (n > 3)
      c.error(second.loc, "read-port",
              fmt::format("a co-issued pair may read at most 3 distinct {}# registers; this "
                          "pair reads {}",
                          reg_name(f, 0).substr(0, 1), n));
  }
}

} // namespace

void check_registers(Ctx& c) {
  const auto& code = c.prog.code;
  for (size_t i = 0; i < code.size(); ++i) {
    const ir::Instruction& ins = code[i];
    if (ins.dst) {
      check_index(c, ins.dst->file, ins.dst->index, ins.dst->loc);
      check_relative(c, ins.dst->file, ins.dst->index, ins.dst->rel, ins.dst->loc);
    }
    if (ins.pred) check_index(c, ins.pred->file, ins.pred->index, ins.pred->loc);
    for (const ir::SrcOperand& s : ins.src) {
      check_index(c, s.file, s.index, s.loc);
      check_relative(c, s);
    }
    check_access(c, ins);
    check_ports(c, ins);
    if (ins.coissue && i > 0 && c.ps1x()) check_pair_ports(c, code[i - 1], ins);
  }
  for (const ir::Declaration& d : c.prog.decls) check_index(c, d.reg.file, d.reg.index, d.reg.loc);
  for (const ir::ConstDef& d : c.prog.defs) check_index(c, d.file, d.index, d.loc);
}

} // namespace tierlift::assembly::detail
