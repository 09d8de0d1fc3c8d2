// Direct3D 9 token stream → ir::Program: version token, statements, comment blocks, end
// token.
// Operand counts come from the opcode table (SM1 has no length field); in SM2 the length
// field is checked against what the operands actually take.
#include <algorithm>

#include <fmt/format.h>

#include "tierlift/assembly/bytecode.h"
#include "token_layout.h"
#include "token_reader.h"

namespace tierlift::assembly {
namespace bc {

bool TokenReader::fail(size_t at, const std::string& message) {
  std::string head = at < t_.size() ? fmt::format("token {} (0x{:08X})", at, t_[at])
                                    : fmt::format("token {} (past the end)", at);
  diags_.error(loc_at(std::min(at, t_.size())), "bytecode", head + ": " + message);
  return false;
}

bool TokenReader::next(uint32_t& tok, size_t& at) {
  if (pos_ >= limit_) {
    if (sized_)
      return fail(instr_at_, fmt::format("instruction length {} is too short for its operands",
                                         limit_ - instr_at_ - 1));
    return fail(instr_at_, "truncated: the stream ends inside this instruction");
  }
  at = pos_;
  tok = t_[pos_++];
  return true;
}

bool TokenReader::version() {
  if (t_.empty()) return fail(0, "empty token stream: no version token");
  auto profile = ir::profile_from_version_token(t_[0]);
  if (!profile) {
    uint32_t kind = t_[0] >> 16;
    if (kind == 0xFFFE || kind == 0xFFFF)
      return fail(0, fmt::format("{} shader version {}.{} is not one of vs_1_1, vs_2_0, "
                                 "vs_2_x, vs_3_0, ps_1_1..ps_1_4, ps_2_0, ps_2_x, ps_3_0",
                                 kind == 0xFFFE ? "vertex" : "pixel", (t_[0] >> 8) & 0xFF,
                                 t_[0] & 0xFF));
    return fail(0, "not a shader version token (expected 0xFFFE.... or 0xFFFF....)");
  }
  p_.profile = *profile;
  p_.version_loc = loc_at(0);
  pos_ = 1;
  return true;
}

std::optional<ir::Program> TokenReader::run() {
  if (!version()) return std::nullopt;
  for (;;) {
    if (pos_ >= t_.size()) {
      fail(pos_,
           fmt::format("missing end token 0x0000FFFF (stream ends after {} tokens)", t_.size()));
      return std::nullopt;
    }
    uint32_t tok = t_[pos_];
    uint16_t opcode = static_cast<uint16_t>(tok & kOpcodeMask);
    if (opcode == kEndOpcode) {
      if (tok != kEndToken) {
        fail(pos_, "end token with bits 16-31 set");
        return std::nullopt;
      }
      if (++pos_ != t_.size()) {
        fail(pos_,
             fmt::format("{} token(s) of trailing data after the end token", t_.size() - pos_));
        return std::nullopt;
      }
      return std::move(p_);
    }
    if (opcode == kCommentOpcode) {
      // Comments (CTAB and the like) mean nothing to the shader, but they are kept word
      // for word: assembling the disassembly must give back the same bytes.
      if (tok & kParamBit) {
        fail(pos_, "comment token with bit 31 set");
        return std::nullopt;
      }
      size_t n = (tok & kCommentSizeMask) >> kCommentSizeShift;
      size_t left = t_.size() - pos_ - 1;
      if (n > left) {
        fail(pos_, fmt::format("comment of {} DWORDs runs past the end ({} left)", n, left));
        return std::nullopt;
      }
      ir::CommentBlock block;
      block.loc = loc_at(pos_);
      block.seq = seq_++;
      block.words.assign(t_.begin() + static_cast<std::ptrdiff_t>(pos_ + 1),
                         t_.begin() + static_cast<std::ptrdiff_t>(pos_ + 1 + n));
      p_.comments.push_back(std::move(block));
      pos_ += 1 + n;
      continue;
    }
    if (!statement()) return std::nullopt;
  }
}

const ir::OpInfo* TokenReader::lookup(uint32_t tok) {
  uint16_t code = static_cast<uint16_t>(tok & kOpcodeMask);
  uint8_t control = static_cast<uint8_t>((tok & kControlMask) >> kControlShift);
  if (const ir::OpInfo* info = ir::find_opcode_by_code(code, control, p_.profile)) return info;
  // Name what the opcode is, when the table knows it in another profile.
  for (const ir::OpInfo& row : ir::opcode_table()) {
    if (row.code != code || row.control != control) continue;
    fail(pos_, fmt::format("'{}' (opcode 0x{:02X}) is not an instruction of {}", row.mnemonic, code,
                           ir::profile_name(p_.profile)));
    return nullptr;
  }
  for (const ir::OpInfo& row : ir::opcode_table())
    if (row.code == code && ir::legal_in(row, p_.profile)) {
      fail(pos_, fmt::format("unknown control value {} for opcode 0x{:02X}", control, code));
      return nullptr;
    }
  fail(pos_, fmt::format("unknown opcode 0x{:04X} in {}", code, ir::profile_name(p_.profile)));
  return nullptr;
}

bool TokenReader::statement() {
  uint32_t tok = t_[pos_];
  instr_at_ = pos_;
  const uint32_t reserved =
      ir::has_predication(p_.profile) ? (kInstrReserved & ~kPredicatedBit) : kInstrReserved;
  if (tok & reserved) {
    const char* which = (tok & kParamBit)        ? "bit 31 set (a parameter token where an "
                                                   "instruction was expected)"
                        : (tok & kPredicatedBit) ? "predicated bit set (only vs_2_x, ps_2_x "
                                                   "and 3.0 have predicates)"
                                                 : "reserved bit 29 set";
    return fail(pos_, which);
  }
  const ir::OpInfo* info = lookup(tok);
  if (!info) return false;
  if ((tok & kPredicatedBit) && info->cls == ir::OpClass::Decl)
    return fail(pos_, "predicated bit set on a declaration or definition");
  if ((tok & kCoissueBit) && (!ir::is_ps1x(p_.profile) || info->cls == ir::OpClass::Decl))
    return fail(pos_, fmt::format("co-issue bit set on '{}' in {}", info->mnemonic,
                                  ir::profile_name(p_.profile)));
  size_t length = (tok & kLengthMask) >> kLengthShift;
  if (has_length_field(p_.profile)) {
    if (length > t_.size() - pos_ - 1)
      return fail(pos_, fmt::format("truncated: instruction length {} runs past the end ({} "
                                    "tokens left)",
                                    length, t_.size() - pos_ - 1));
    limit_ = pos_ + 1 + length;
    sized_ = true;
  } else {
    if (length != 0) return fail(pos_, "instruction length bits 24-27 set in a 1.x shader");
    limit_ = t_.size();
    sized_ = false;
  }
  ++pos_;
  bool ok = info->op == ir::Opcode::Dcl      ? declaration()
            : info->cls == ir::OpClass::Decl ? definition(*info)
                                             : instruction(*info, tok);
  if (!ok) return false;
  if (sized_ && pos_ != limit_)
    return fail(instr_at_, fmt::format("instruction length {} but its operands take {}", length,
                                       pos_ - instr_at_ - 1));
  return true;
}

bool TokenReader::instruction(const ir::OpInfo& info, uint32_t tok) {
  ir::Instruction ins;
  ins.op = info.op;
  ins.coissue = (tok & kCoissueBit) != 0;
  ins.loc = loc();
  ins.seq = seq_++;
  uint32_t t = 0;
  size_t at = 0;
  if (info.has_dst) {
    ir::DstOperand d;
    if (!next(t, at) || !dst(t, at, d, ins.mods)) return false;
    ins.dst = d;
  }
  if (tok & kPredicatedBit) {
    // p0 follows the destination (docs/d3d9-rules.md §11.1).
    ir::SrcOperand pr;
    if (!next(t, at) || !src(t, at, pr)) return false;
    if (pr.file != ir::RegFile::Predicate || pr.rel ||
        (pr.mod != ir::SrcMod::None && pr.mod != ir::SrcMod::Not))
      return fail(at, "the predicate token of a predicated instruction must be p0 or !p0");
    ins.pred = pr;
  }
  for (int i = 0; i < info.num_src; ++i) {
    ir::SrcOperand s;
    if (!next(t, at) || !src(t, at, s)) return false;
    ins.src.push_back(s);
  }
  p_.code.push_back(std::move(ins));
  return true;
}

bool TokenReader::declaration() {
  ir::Declaration d;
  d.loc = loc();
  d.seq = seq_++;
  uint32_t usage = 0, t = 0;
  size_t usage_at = 0, at = 0;
  if (!next(usage, usage_at) || !next(t, at) || !dst(t, at, d.reg, d.mods)) return false;
  if (!(usage & kParamBit)) return fail(usage_at, "dcl usage token without bit 31");
  if (d.reg.rel) return fail(at, "a declaration of a relatively addressed register");
  if (d.reg.file == ir::RegFile::Sampler) {
    if (usage & ~(kParamBit | kSamplerTypeMask))
      return fail(usage_at, "reserved bits set in a sampler declaration");
    uint32_t type = (usage & kSamplerTypeMask) >> kSamplerTypeShift;
    if (type != 2 && type != 3 && type != 4)
      return fail(usage_at,
                  fmt::format("sampler type {} is not 2d (2), cube (3) or volume (4)", type));
    d.sampler_type = static_cast<ir::SamplerType>(type);
  } else if ((p_.stage() == ir::ShaderStage::Vertex && d.reg.file == ir::RegFile::Input) ||
             (p_.profile == ir::Profile::vs_3_0 && d.reg.file == ir::RegFile::Output) ||
             (p_.profile == ir::Profile::ps_3_0 && d.reg.file == ir::RegFile::Input)) {
    if (usage & ~(kParamBit | kUsageMask | kUsageIndexMask))
      return fail(usage_at, "reserved bits set in an input or output declaration");
    uint32_t u = usage & kUsageMask;
    if (u > static_cast<uint32_t>(ir::DeclUsage::Sample))
      return fail(usage_at, fmt::format("unknown declaration usage {}", u));
    d.usage = static_cast<ir::DeclUsage>(u);
    d.usage_index = static_cast<uint8_t>((usage & kUsageIndexMask) >> kUsageIndexShift);
  } else if (p_.stage() == ir::ShaderStage::Pixel &&
             (d.reg.file == ir::RegFile::Input || d.reg.file == ir::RegFile::Texture ||
              d.reg.file == ir::RegFile::Misc)) {
    if (usage != kParamBit)
      return fail(usage_at, "ps_2_0 v#/t# and ps_3_0 vPos/vFace declarations carry usage 0");
  } else {
    return fail(at, fmt::format("{} cannot be declared in {}",
                                ir::register_name(d.reg.file, d.reg.index),
                                ir::profile_name(p_.profile)));
  }
  // Only pixel-shader v#/t# declarations (and ps_3_0 samplers) take modifiers (_pp,
  // _centroid); nothing takes _sat or a shift, and the text syntax has no way to say them.
  bool ps_input = p_.stage() == ir::ShaderStage::Pixel &&
                  (d.reg.file != ir::RegFile::Sampler || p_.profile == ir::Profile::ps_3_0);
  if (d.mods.sat || d.mods.shift != 0 || (!ps_input && (d.mods.pp || d.mods.centroid)))
    return fail(at, "result modifier or shift on this declaration");
  p_.decls.push_back(d);
  return true;
}

bool TokenReader::definition(const ir::OpInfo& info) {
  ir::ConstDef c;
  c.loc = loc();
  c.seq = seq_++;
  ir::RegFile want = info.op == ir::Opcode::DefI   ? ir::RegFile::ConstInt
                     : info.op == ir::Opcode::DefB ? ir::RegFile::ConstBool
                                                   : ir::RegFile::Const;
  ir::DstOperand d;
  ir::InstrMods mods;
  uint32_t t = 0;
  size_t at = 0;
  if (!next(t, at) || !dst(t, at, d, mods)) return false;
  if (d.file != want)
    return fail(at, fmt::format("'{}' defines {}, not {}", info.mnemonic,
                                ir::register_name(want, 0).substr(0, 1) + "#",
                                ir::register_name(d.file, d.index)));
  if (d.mask != ir::kFullMask || mods.sat || mods.pp || mods.centroid || mods.shift != 0 || d.rel)
    return fail(at, "a constant definition takes a full write mask and no modifiers");
  c.file = d.file;
  c.index = d.index;
  int count = info.op == ir::Opcode::DefB ? 1 : 4;
  for (int i = 0; i < count; ++i) {
    if (!next(t, at)) return false;
    c.raw[i] = t; // raw bits: NaN, -0 and denormals survive unchanged
  }
  if (info.op == ir::Opcode::DefB && c.raw[0] > 1)
    return fail(at, "defb value must be 0 (false) or 1 (true)");
  p_.defs.push_back(c);
  return true;
}

} // namespace bc

std::optional<ir::Program> disassemble(const std::vector<uint32_t>& tokens,
                                       ir::DiagnosticSink& diags, uint32_t file) {
  return bc::TokenReader(tokens, diags, file).run();
}

} // namespace tierlift::assembly
