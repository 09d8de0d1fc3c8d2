// Telling the forms of a listing file apart by content (load.h).
#include <fmt/format.h>

#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/load.h"

namespace tierlift::assembly {
namespace {

uint32_t le32(std::string_view b, size_t i) {
  auto u = [&](size_t k) { return uint32_t{static_cast<unsigned char>(b[i + k])}; };
  return u(0) | (u(1) << 8) | (u(2) << 16) | (u(3) << 24);
}

bool is_version_token(uint32_t t) {
  return (t >> 16) == 0xFFFE || (t >> 16) == 0xFFFF;
}

// Text: no NUL or control characters other than white space, once the NUL padding some
// tools append is left out. Bytes above 0x7F need not be UTF-8: comments in a legacy 8-bit
// code page (Windows-1252, -1251) are common in shipped listings, and the lexer skips
// comments unread (outside a comment such a byte is still an error there, with its line).
bool looks_like_text(std::string_view b) {
  b = without_trailing_nuls(b);
  for (unsigned char c : b)
    if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v') || c == 0x7F)
      return false;
  return true;
}

// A C array (or bare list) of numbers whose first value is a version token. Assembly text
// never holds '{' or starts with a number, so the scanner fails on it at once.
bool is_token_array(std::string_view b) {
  if (b.find_first_of("{,") == std::string_view::npos) return false;
  ir::DiagnosticSink scratch;
  auto tokens = read_token_file(std::string(b), scratch, 0);
  return tokens && !tokens->empty() && is_version_token(tokens->front());
}

} // namespace

std::string_view without_trailing_nuls(std::string_view bytes) {
  return bytes.substr(0, bytes.find_last_not_of('\0') + 1);
}

std::string_view listing_form_name(ListingForm form) {
  switch (form) {
  case ListingForm::Text: return "assembly text";
  case ListingForm::TokenStream: return "D3D9 token stream";
  case ListingForm::TokenArray: return "D3D9 token stream as a C array";
  case ListingForm::Binary: return "binary file";
  }
  return "?";
}

ListingForm detect_listing_form(std::string_view bytes) {
  if (bytes.size() >= 4 && bytes.size() % 4 == 0 && is_version_token(le32(bytes, 0)))
    return ListingForm::TokenStream;
  if (!looks_like_text(bytes)) return ListingForm::Binary;
  if (is_token_array(without_trailing_nuls(bytes))) return ListingForm::TokenArray;
  return ListingForm::Text;
}

std::string describe_binary(std::string_view b) {
  auto starts = [&](std::string_view magic) { return b.substr(0, magic.size()) == magic; };
  if (starts("\x89PNG"))
    return "a PNG image, not a shader; `tierlift glow --image` and `tierlift run --texture` "
           "take images";
  if (starts("DXBC"))
    return "a DXBC container (Direct3D 10 or later), not a Direct3D 9 token stream; tierlift "
           "reads vs_1_1..ps_2_0 only";
  if (b.size() >= 4 && (le32(b, 0) >> 16) == 0xFEFF)
    return "a D3DX effect binary (fx_2_0/fx_1_1), not a single shader; compile each shader "
           "on its own (fxc /T vs_2_0 …) and give `tierlift check` the result";
  if (starts("PF\n") || starts("Pf\n"))
    return "a PFM image, not a shader; `tierlift run --texture` takes it";
  if (starts("\x7F"
             "ELF") ||
      starts("MZ"))
    return "an executable, not a shader listing or a token stream";
  if (b.size() >= 4 && b.size() % 4 != 0 && (le32(b, 0) >> 16) >= 0xFFFE)
    return fmt::format("a token stream cut short: {} bytes is not a whole number of DWORDs",
                       b.size());
  return "a binary file, neither shader assembly text nor a D3D9 token stream (which starts "
         "with a version token 0xFFFE0101..0xFFFF0200); `tierlift disasm` reads token streams, "
         "`tierlift check` reads both";
}

} // namespace tierlift::assembly
