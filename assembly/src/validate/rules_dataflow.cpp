// Reads of never-written registers, component by component (through write masks, swizzles
// and what each operation consumes): r# everywhere, t# in ps_1_1–1_3 (written by texture
// instructions or arithmetic), a0 before relative use. Co-issued halves read before either
// writes; a ps_1_4 `phase` drops the alpha of every r#; a vs_2_0 call brings in what its
// subroutine writes. Also the ps_2_0 dependent-read depth.
#include <algorithm>
#include <map>

#include "context.h"

namespace tierlift::assembly::detail {
namespace {

using ir::Opcode;
using ir::RegFile;

using Key = std::pair<RegFile, uint32_t>;

bool is_data_kind(ir::OperandKind k) {
  using K = ir::OperandKind;
  return k != K::Sampler && k != K::Bool && k != K::Int && k != K::Label && k != K::LoopReg;
}

struct Flow {
  explicit Flow(Ctx& ctx) : c(ctx) {}
  Ctx& c;
  std::map<Key, uint8_t> written;
  std::map<Key, std::string> killed;   // register → the instruction that consumed it
  std::map<uint32_t, bool> alpha_lost; // r# whose alpha a ps_1_4 phase dropped
  std::map<uint32_t, int> level;       // ps_2_0: texture-read depth of the value in r#
  std::map<uint32_t, std::map<Key, uint8_t>> sub_writes; // label → writes of its body

  bool tracked(RegFile f) const {
    return f == RegFile::Temp || (f == RegFile::Texture && c.ps11_13()) || f == RegFile::Addr ||
           f == RegFile::Predicate;
  }

  void need(RegFile f, uint32_t index, uint8_t comps, const ir::SourceLoc& loc) {
    if (!tracked(f) || comps == 0) return;
    uint8_t missing = comps & ~written[{f, index}];
    if (!missing) return;
    std::string why;
    if (auto k = killed.find({f, index}); k != killed.end())
      why = fmt::format(" ({} left it unusable)", k->second);
    else if (f == RegFile::Temp && c.ps14() && (missing & 8) && alpha_lost[index])
      why = " (ps_1_4 does not keep the alpha of r# across phase)";
    c.error(loc, "read-before-write",
            fmt::format("{} is read before it is written{}", reg_comps(f, index, missing), why));
    written[{f, index}] |= missing; // report each missing component once
  }

  int sampler_dim_of(const ir::Instruction& ins) const {
    if (ins.src.size() > 1 && ins.src[1].file == RegFile::Sampler)
      return sampler_dim(c.prog, ins.src[1].index);
    return 3;
  }

  void reads(const ir::Instruction& ins) {
    const ir::OpInfo& info = info_of(ins);
    if (ins.pred)
      need(RegFile::Predicate, 0,
           ir::is_replicate(ins.pred->swizzle)
               ? static_cast<uint8_t>(1 << (ins.pred->swizzle & 3))
               : (ins.dst ? ins.dst->mask : uint8_t{0xF}), // p0.x gates .x, p0.y .y, ...
           ins.pred->loc);
    for (size_t k = 0; k < ins.src.size(); ++k) {
      const ir::SrcOperand& s = ins.src[k];
      // Labels, b#, i#, aL and samplers carry no data; a wrong register there is an
      // operand-kind error already.
      if (k < info.num_src && !is_data_kind(info.src[k])) continue;
      if (s.rel && s.rel->file == RegFile::Addr)
        need(RegFile::Addr, 0, static_cast<uint8_t>(1 << (s.rel->component & 3)),
             s.rel->loc.valid() ? s.rel->loc : s.loc);
      if (s.file == RegFile::Addr) continue; // reported as an access error
      need(s.file, s.index, ir::source_read_mask(ins, k, c.target, sampler_dim_of(ins)), s.loc);
    }
    if (!ins.dst) return;
    const ir::DstOperand& d = *ins.dst;
    // texkill tests .xyz in ps_1_4 and all four components in ps_2_0 (doc conflict "first
    // three" vs translators' four; tierlift follows the translators).
    if (ins.op == Opcode::TexKill && !c.ps11_13())
      need(d.file, d.index, c.ps14() ? 0x7 : 0xF, d.loc);
    if (ins.op == Opcode::TexDepth) need(d.file, d.index, 0x3, d.loc);
  }

  void writes(const ir::Instruction& ins) {
    if (ins.op == Opcode::Call || ins.op == Opcode::CallNz) {
      if (!ins.src.empty())
        for (auto& [k, m] : sub_writes[ins.src[0].index]) written[k] |= m;
      return;
    }
    if (!ins.dst || !tracked(ins.dst->file)) return;
    Key key{ins.dst->file, ins.dst->index};
    // texdepth (r5) and texm3x2depth (t(m+1)) leave their register unusable afterwards.
    // (A texm3x2pad/texm3x3pad register reads as never written: the documentation calls
    // reading it undefined, unconfirmed.)
    if (ir::has_implicit(ins, ir::kWritesDepth)) {
      written[key] = 0;
      killed[key] = std::string(mnemonic(ins));
      return;
    }
    killed.erase(key);
    written[key] |= ir::written_mask(ins, c.target);
    if (ins.dst->file == RegFile::Temp) alpha_lost[ins.dst->index] = false;
  }

  // ps_2_0 without NODEPENDENTREADLIMIT: at most 4 levels of texture reads (docs/d3d9-rules.md
  // §5.7). The doc's second trigger (a texld whose destination was written before) is not
  // modelled: only the data dependence through src0 counts.
  void dependent_reads(const ir::Instruction& ins) {
    // ps_2_0, and ps_2_x whose caps keep the limit (ps_2_b); 3.0 has none.
    if (!c.ps2up() || c.caps.no_dependent_limit || c.sm3() || !ins.dst ||
        ins.dst->file != RegFile::Temp)
      return;
    int lvl = 0;
    for (const ir::SrcOperand& s : ins.src)
      if (s.file == RegFile::Temp) lvl = std::max(lvl, level[s.index]);
    if (is_texture_op(ins) && ins.op != Opcode::TexKill) {
      ++lvl;
      if (lvl == 5)
        c.error(ins.loc, "dependent-read",
                fmt::format("{} allows 4 levels of dependent texture reads; this texld is the 5th",
                            c.pname()));
    }
    int& slot = level[ins.dst->index];
    slot = ins.dst->mask == ir::kFullMask ? lvl : std::max(slot, lvl);
  }

  void prepass_subroutines() {
    uint32_t current = 0;
    bool in_sub = false;
    for (const ir::Instruction& ins : c.prog.code) {
      if (ins.op == Opcode::Label && !ins.src.empty()) {
        current = ins.src[0].index;
        in_sub = true;
      } else if (in_sub && ins.dst && tracked(ins.dst->file)) {
        sub_writes[current][{ins.dst->file, ins.dst->index}] |= ir::written_mask(ins, c.target);
      }
    }
  }

  void run() {
    prepass_subroutines();
    const auto& code = c.prog.code;
    for (size_t i = 0; i < code.size(); ++i) {
      const ir::Instruction& ins = code[i];
      if (ins.op == Opcode::Phase) {
        for (auto& [k, m] : written)
          if (k.first == RegFile::Temp && (m & 8)) {
            m &= 0x7;
            alpha_lost[k.second] = true;
          }
        continue;
      }
      bool pair = c.ps1x() && i + 1 < code.size() && code[i + 1].coissue;
      reads(ins);
      if (pair) reads(code[i + 1]); // both halves read before either writes
      dependent_reads(ins);
      writes(ins);
      if (pair) {
        writes(code[i + 1]);
        ++i;
      }
    }
  }
};

} // namespace

void check_dataflow(Ctx& c) {
  Flow(c).run();
}

} // namespace tierlift::assembly::detail
