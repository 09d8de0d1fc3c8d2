// Reading the CTAB comment (constant_table.h). Every read is bounds-checked against the
// comment's own bytes: a table from an untrusted file can point anywhere.
#include "tierlift/assembly/constant_table.h"

#include <algorithm>

#include <fmt/format.h>

namespace tierlift::assembly {
namespace {

constexpr uint32_t kCommentOpcode = 0xFFFE;
constexpr uint32_t kCtabFourcc = 0x42415443; // "CTAB" little-endian
constexpr size_t kHeaderBytes = 28, kInfoBytes = 20, kTypeBytes = 16;

class Blob {
public:
  explicit Blob(std::string bytes) : b_(std::move(bytes)) {}
  bool has(size_t ofs, size_t n) const { return ofs <= b_.size() && n <= b_.size() - ofs; }
  uint32_t u16(size_t ofs) const { return byte(ofs) | (byte(ofs + 1) << 8); }
  uint32_t u32(size_t ofs) const { return u16(ofs) | (u16(ofs + 2) << 16); }
  // A NUL-terminated string at `ofs`; nullopt when it runs off the end.
  std::optional<std::string> str(size_t ofs) const {
    if (ofs >= b_.size()) return std::nullopt;
    size_t end = b_.find('\0', ofs);
    if (end == std::string::npos) return std::nullopt;
    return b_.substr(ofs, end - ofs);
  }

private:
  uint32_t byte(size_t i) const { return static_cast<unsigned char>(b_[i]); }
  std::string b_;
};

std::string type_name(uint32_t cls, uint32_t type, uint32_t rows, uint32_t cols, uint32_t elems) {
  static constexpr const char* kTypes[] = {"void",      "bool",        "int",        "float",
                                           "string",    "texture",     "texture1D",  "texture2D",
                                           "texture3D", "textureCUBE", "sampler",    "sampler1D",
                                           "sampler2D", "sampler3D",   "samplerCUBE"};
  std::string base = type < std::size(kTypes) ? kTypes[type] : fmt::format("type{}", type);
  std::string out = base;
  if (cls == 1) out = fmt::format("{}{}", base, cols);                      // vector
  if (cls == 2 || cls == 3) out = fmt::format("{}{}x{}", base, rows, cols); // matrix
  if (cls == 5) out = "struct";
  if (elems > 1) out += fmt::format("[{}]", elems);
  return out;
}

std::optional<ConstantTable> parse(const Blob& b, std::string& error) {
  if (!b.has(0, kHeaderBytes) || b.u32(0) != kHeaderBytes) {
    error = "its header is not the 28-byte D3DXSHADER_CONSTANTTABLE";
    return std::nullopt;
  }
  ConstantTable t;
  t.creator = b.str(b.u32(4)).value_or("");
  t.target = b.str(b.u32(24)).value_or("");
  uint32_t count = b.u32(12), info = b.u32(16);
  if (!b.has(info, size_t{count} * kInfoBytes)) {
    error = fmt::format("its {} constant records run past the comment", count);
    return std::nullopt;
  }
  for (uint32_t i = 0; i < count; ++i) {
    size_t at = info + size_t{i} * kInfoBytes;
    NamedConstant c;
    auto name = b.str(b.u32(at));
    if (!name || name->empty()) {
      error = fmt::format("constant {} has no readable name", i);
      return std::nullopt;
    }
    c.name = *name;
    uint32_t set = b.u16(at + 4);
    if (set > 3) {
      error = fmt::format("constant '{}' has register set {} (expected 0..3)", c.name, set);
      return std::nullopt;
    }
    c.set = static_cast<ConstantSet>(set);
    c.index = b.u16(at + 6);
    c.count = b.u16(at + 8);
    uint32_t type = b.u32(at + 12);
    if (b.has(type, kTypeBytes))
      c.type = type_name(b.u16(type), b.u16(type + 2), b.u16(type + 4), b.u16(type + 6),
                         b.u16(type + 8));
    t.constants.push_back(std::move(c));
  }
  return t;
}

} // namespace

ir::RegFile NamedConstant::file() const {
  switch (set) {
  case ConstantSet::Bool: return ir::RegFile::ConstBool;
  case ConstantSet::Int4: return ir::RegFile::ConstInt;
  case ConstantSet::Sampler: return ir::RegFile::Sampler;
  case ConstantSet::Float4: break;
  }
  return ir::RegFile::Const;
}

std::string NamedConstant::registers() const {
  std::string first = ir::register_name(file(), index);
  if (count <= 1) return first;
  return fmt::format("{}..{}", first, ir::register_name(file(), index + count - 1));
}

const NamedConstant* ConstantTable::find(std::string_view name) const {
  for (const NamedConstant& c : constants)
    if (c.name == name) return &c;
  return nullptr;
}

std::string print_constant_table(const ConstantTable& table) {
  std::string out = "// CTAB";
  if (!table.target.empty()) out += ": " + table.target;
  if (!table.creator.empty()) out += (table.target.empty() ? ": " : ", ") + table.creator;
  out += '\n';
  size_t width = 0;
  for (const NamedConstant& c : table.constants) width = std::max(width, c.registers().size());
  for (const NamedConstant& c : table.constants)
    out += fmt::format("//   {:<{}}  {}{}\n", c.registers(), width, c.name,
                       c.type.empty() ? "" : "  " + c.type);
  return out;
}

std::optional<ConstantTable> read_constant_table(const std::vector<uint32_t>& tokens,
                                                 ir::DiagnosticSink& diags, uint32_t file) {
  // Comments sit between instructions; fxc puts the CTAB right after the version token.
  for (size_t i = 1; i < tokens.size() && (tokens[i] & 0xFFFF) == kCommentOpcode;) {
    size_t n = (tokens[i] >> 16) & 0x7FFF;
    if (n > tokens.size() - i - 1) return std::nullopt; // the reader reports the overrun
    if (n >= 1 && tokens[i + 1] == kCtabFourcc) {
      std::string bytes;
      for (size_t k = i + 2; k < i + 1 + n; ++k)
        for (int s = 0; s < 32; s += 8) bytes += static_cast<char>((tokens[k] >> s) & 0xFF);
      std::string error;
      if (auto table = parse(Blob(std::move(bytes)), error)) return table;
      diags.warning(ir::SourceLoc::at_byte(file, 4 * i), "constant-table",
                    fmt::format("the CTAB comment is unreadable ({}); constant names are not "
                                "available",
                                error));
      return std::nullopt;
    }
    i += 1 + n;
  }
  return std::nullopt;
}

} // namespace tierlift::assembly
