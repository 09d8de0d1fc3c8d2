// ir::Program → Direct3D 9 token stream, laid out as Microsoft's assembler lays it out:
// version token, every statement and comment block in listing order, end token. Opcodes and operand
// shapes come from the one opcode table; token bit positions from token_layout.h.
#include <fmt/format.h>

#include "tierlift/assembly/bytecode.h"
#include "token_layout.h"

namespace tierlift::assembly {
namespace {

using ir::RegFile;

class Writer {
public:
  Writer(const ir::Program& p, ir::DiagnosticSink* diags) : p_(p), diags_(diags) {}

  std::vector<uint32_t> run() {
    out_.push_back(ir::version_token(p_.profile));
    for (const auto& st : p_.statements()) {
      switch (st.kind) {
      case ir::Program::Statement::Kind::Decl: declaration(p_.decls[st.index]); break;
      case ir::Program::Statement::Kind::Def: definition(p_.defs[st.index]); break;
      case ir::Program::Statement::Kind::Code: instruction(p_.code[st.index]); break;
      case ir::Program::Statement::Kind::Comment: comment(p_.comments[st.index]); break;
      }
    }
    out_.push_back(bc::kEndToken);
    return std::move(out_);
  }
  bool failed() const { return failed_; }

private:
  // Only the checked form reports; the plain form truncates fields silently.
  void problem(const ir::SourceLoc& loc, std::string message) {
    failed_ = true;
    if (diags_) diags_->error(loc, "bytecode", "cannot encode: " + message);
  }

  bool sm2() const { return bc::has_length_field(p_.profile); }

  // Type 3 means a0 in a vertex shader and t# in a pixel shader: the IR file must match the
  // stage, or the reader would give back the other one.
  void check_register(RegFile file, uint32_t index, const ir::SourceLoc& loc) {
    if (index > bc::kMaxRegNum)
      problem(loc, fmt::format("register number {} does not fit 11 bits", index));
    if ((file == RegFile::Addr && p_.stage() == ir::ShaderStage::Pixel) ||
        (file == RegFile::Texture && p_.stage() == ir::ShaderStage::Vertex))
      problem(loc,
              fmt::format("{} has no register type in a {} shader", ir::register_name(file, index),
                          p_.stage() == ir::ShaderStage::Pixel ? "pixel" : "vertex"));
  }

  uint32_t register_bits(RegFile file, uint32_t index) const {
    return bc::kParamBit | bc::encode_regtype(ir::bytecode_regtype(file)) |
           (index & bc::kRegNumMask);
  }

  uint32_t dst_token(const ir::DstOperand& d, const ir::InstrMods& mods) {
    check_register(d.file, d.index, d.loc);
    if (d.rel) problem(d.loc, "relative destination outside an instruction");
    if ((d.mask & ir::kFullMask) == 0) problem(d.loc, "empty write mask");
    // x2/x4/x8 and d2/d4/d8 only: the reader rejects the other values of the 4-bit field.
    if (mods.shift < -3 || mods.shift > 3)
      problem(d.loc, fmt::format("shift {} is not one of x2, x4, x8, d2, d4, d8", mods.shift));
    uint32_t resmod = (mods.sat ? bc::kResultSat : 0) | (mods.pp ? bc::kResultPp : 0) |
                      (mods.centroid ? bc::kResultCentroid : 0);
    return register_bits(d.file, d.index) | ((uint32_t{d.mask} << bc::kMaskShift) & bc::kMaskMask) |
           (resmod << bc::kResultModShift) | bc::encode_shift(mods.shift);
  }

  // One source token, plus the address token that SM2 appends for relative addressing.
  void src_tokens(const ir::SrcOperand& s, std::vector<uint32_t>& body) {
    check_register(s.file, s.index, s.loc);
    uint32_t mod = static_cast<uint32_t>(s.mod);
    if (mod > static_cast<uint32_t>(ir::SrcMod::Not)) problem(s.loc, "unknown source modifier");
    uint32_t tok = register_bits(s.file, s.index) | (uint32_t{s.swizzle} << bc::kSwizzleShift) |
                   ((mod << bc::kSrcModShift) & bc::kSrcModMask);
    if (!s.rel) {
      body.push_back(tok);
      return;
    }
    body.push_back(tok | bc::kRelativeBit);
    if (p_.stage() != ir::ShaderStage::Vertex && p_.profile != ir::Profile::ps_3_0) {
      problem(s.loc, "pixel shaders before ps_3_0 have no relative addressing");
      return;
    }
    if (!sm2()) {
      // vs_1_1: bit 13 alone; the index register is always a0.x.
      if (s.rel->file != RegFile::Addr || s.rel->component != 0)
        problem(s.rel->loc, "vs_1_1 relative addressing can only use a0.x");
      return;
    }
    address_token(*s.rel, body);
  }

  // SM2+: the token after a relative operand names a0 (with its swizzle) or aL.
  void address_token(const ir::RelAddr& rel, std::vector<uint32_t>& body) {
    if (rel.file != RegFile::Addr && rel.file != RegFile::Loop)
      problem(rel.loc, "relative addressing needs a0 or aL");
    if (rel.component > 3) problem(rel.loc, "relative component out of range");
    body.push_back(register_bits(rel.file, 0) |
                   (uint32_t{rel.token_swizzle()} << bc::kSwizzleShift));
  }

  // The destination, and the address token of o[a0.x + n] (vs_3_0).
  void dst_tokens(const ir::DstOperand& d, const ir::InstrMods& mods, std::vector<uint32_t>& body) {
    ir::DstOperand plain = d;
    plain.rel.reset();
    uint32_t tok = dst_token(plain, mods);
    if (!d.rel) {
      body.push_back(tok);
      return;
    }
    body.push_back(tok | bc::kRelativeBit);
    if (p_.profile != ir::Profile::vs_3_0)
      problem(d.loc, "only vs_3_0 addresses a destination relatively");
    address_token(*d.rel, body);
  }

  void emit(const ir::OpInfo& info, bool coissue, const std::vector<uint32_t>& body,
            bool predicated = false) {
    uint32_t tok = uint32_t{info.code} | (uint32_t{info.control} << bc::kControlShift);
    if (predicated) tok |= bc::kPredicatedBit;
    // The longest body is 7 tokens (three relative sources), far below the 4-bit limit.
    if (sm2()) tok |= (static_cast<uint32_t>(body.size()) << bc::kLengthShift) & bc::kLengthMask;
    if (coissue) tok |= bc::kCoissueBit;
    out_.push_back(tok);
    out_.insert(out_.end(), body.begin(), body.end());
  }

  void check_legal(const ir::OpInfo& info, const ir::SourceLoc& loc) {
    if (!ir::legal_in(info, p_.profile))
      problem(loc, fmt::format("'{}' is not an instruction of {}", info.mnemonic,
                               ir::profile_name(p_.profile)));
  }

  void instruction(const ir::Instruction& ins) {
    const ir::OpInfo& info = ir::op_info(ins.op);
    check_legal(info, ins.loc);
    if (info.cls == ir::OpClass::Decl) problem(ins.loc, "declaration among the instructions");
    if (ins.dst.has_value() != info.has_dst || ins.src.size() != info.num_src)
      problem(ins.loc, fmt::format("'{}' takes {}{} source(s), not {}{}", info.mnemonic,
                                   info.has_dst ? "a destination and " : "", info.num_src,
                                   ins.dst ? "a destination and " : "", ins.src.size()));
    if (ins.coissue && !ir::is_ps1x(p_.profile)) problem(ins.loc, "co-issue exists only in ps_1_x");
    std::vector<uint32_t> body;
    if (ins.dst) dst_tokens(*ins.dst, ins.mods, body);
    // A predicated instruction carries p0 (its swizzle, ! as SrcMod::Not) right after the
    // destination (Wine's d3dcompiler asm tests: "(!p0) add r2, r2, r3").
    if (ins.pred) {
      if (!ir::has_predication(p_.profile))
        problem(ins.pred->loc, "predicated instructions need vs_2_x, ps_2_x or a 3.0 profile");
      if (ins.pred->rel) problem(ins.pred->loc, "a predicate is not addressed relatively");
      src_tokens(*ins.pred, body);
    }
    for (const auto& s : ins.src) src_tokens(s, body);
    emit(info, ins.coissue, body, ins.pred.has_value());
  }

  void declaration(const ir::Declaration& d) {
    const ir::OpInfo& info = ir::op_info(ir::Opcode::Dcl);
    check_legal(info, d.loc);
    uint32_t usage = bc::kParamBit;
    if (d.reg.file == RegFile::Sampler) {
      usage |= (uint32_t{static_cast<uint8_t>(d.sampler_type)} << bc::kSamplerTypeShift) &
               bc::kSamplerTypeMask;
    } else if (p_.stage() == ir::ShaderStage::Vertex ||
               (p_.profile == ir::Profile::ps_3_0 && d.reg.file == RegFile::Input)) {
      // Vertex inputs and outputs and ps_3_0 inputs carry their semantic; ps_2_0 v#/t# and
      // ps_3_0 vPos/vFace carry usage 0 (Microsoft's layout).
      if (d.usage_index > 15) problem(d.loc, "usage index above 15");
      usage |= (uint32_t{static_cast<uint8_t>(d.usage)} & bc::kUsageMask) |
               ((uint32_t{d.usage_index} << bc::kUsageIndexShift) & bc::kUsageIndexMask);
    }
    // ps_3_0 samplers take _pp / _centroid too (D3DAssemble writes them; Wine's asm tests).
    bool ps_input = p_.stage() == ir::ShaderStage::Pixel &&
                    (d.reg.file != RegFile::Sampler || p_.profile == ir::Profile::ps_3_0);
    if (d.mods.sat || d.mods.shift != 0 || (!ps_input && (d.mods.pp || d.mods.centroid)))
      problem(d.loc, "only pixel-shader declarations take modifiers (_pp, _centroid)");
    if (d.reg.rel) problem(d.loc, "a declaration names one register");
    emit(info, false, {usage, dst_token(d.reg, d.mods)});
  }

  void definition(const ir::ConstDef& c) {
    ir::Opcode op = c.file == RegFile::ConstInt    ? ir::Opcode::DefI
                    : c.file == RegFile::ConstBool ? ir::Opcode::DefB
                                                   : ir::Opcode::Def;
    if (c.file != RegFile::Const && c.file != RegFile::ConstInt && c.file != RegFile::ConstBool)
      problem(c.loc, "constant definition of a register that is not c#, i# or b#");
    const ir::OpInfo& info = ir::op_info(op);
    check_legal(info, c.loc);
    std::vector<uint32_t> body{dst_token({c.file, c.index, ir::kFullMask, c.loc}, {})};
    if (op == ir::Opcode::DefB) {
      if (c.raw[0] > 1) problem(c.loc, "defb value other than 0 or 1");
      body.push_back(c.raw[0]);
    } else {
      body.insert(body.end(), c.raw.begin(), c.raw.end());
    }
    emit(info, false, body);
  }

  // The comment token carries the payload's length in bits 16-30: 32767 DWORDs at most.
  void comment(const ir::CommentBlock& c) {
    constexpr size_t kMaxWords = bc::kCommentSizeMask >> bc::kCommentSizeShift;
    if (c.words.size() > kMaxWords)
      problem(c.loc, fmt::format("a comment block of {} DWORDs (a comment token holds {} at most)",
                                 c.words.size(), kMaxWords));
    out_.push_back(
        uint32_t{bc::kCommentOpcode} |
        ((static_cast<uint32_t>(c.words.size()) << bc::kCommentSizeShift) & bc::kCommentSizeMask));
    out_.insert(out_.end(), c.words.begin(), c.words.end());
  }

  const ir::Program& p_;
  ir::DiagnosticSink* diags_;
  std::vector<uint32_t> out_;
  bool failed_ = false;
};

} // namespace

std::vector<uint32_t> assemble(const ir::Program& program) {
  return Writer(program, nullptr).run();
}

std::optional<std::vector<uint32_t>> assemble(const ir::Program& program,
                                              ir::DiagnosticSink& diags) {
  Writer w(program, &diags);
  std::vector<uint32_t> tokens = w.run();
  if (w.failed()) return std::nullopt;
  return tokens;
}

} // namespace tierlift::assembly
