// The one opcode table. Columns of `slots`: vs_1_1 vs_2_0 ps_1_1 ps_1_2 ps_1_3 ps_1_4 ps_2_0;
// "no" = not legal there. The columns of the 2.x and 3.0 profiles (vs_2_x ps_2_x vs_3_0
// ps_3_0) follow vs_2_0 and ps_2_0 unless kLaterColumns says otherwise; the rows only
// those profiles have (after DefB) give them with later(). Slot costs are the ISA's (macros at
// their expanded size). The semantic columns (matrix rows, written components, source lanes,
// sampling, implicit reads and writes) are added by the wrappers around a row; semantics.h answers
// from them.
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "tierlift/ir/opcodes.h"
#include "tierlift/ir/semantics.h"

namespace tierlift::ir {
namespace {

constexpr int8_t no = -1;
using K = OperandKind;
using S = std::array<int8_t, kProfileCount>;

// One line of the table: the row and its semantic columns.
struct Row {
  OpInfo info;
  OpSemantics sem;
};

constexpr Row row(Opcode op, std::string_view mn, uint16_t code, OpClass cls, bool dst,
                  std::initializer_list<K> srcs, S slots, std::string_view summary,
                  uint8_t control = 0, uint8_t extra_arith = 0) {
  OpInfo info{op,    mn,          code,   control,
              cls,   dst,         0,      {K::None, K::None, K::None, K::None},
              slots, extra_arith, summary};
  for (K k : srcs) info.src[info.num_src++] = k;
  // vs_2_x and vs_3_0 start from vs_2_0, ps_2_x and ps_3_0 from ps_2_0.
  constexpr int vs20 = profile_index(Profile::vs_2_0), ps20 = profile_index(Profile::ps_2_0);
  info.slots[profile_index(Profile::vs_2_x)] = info.slots[vs20];
  info.slots[profile_index(Profile::vs_3_0)] = info.slots[vs20];
  info.slots[profile_index(Profile::ps_2_x)] = info.slots[ps20];
  info.slots[profile_index(Profile::ps_3_0)] = info.slots[ps20];
  return Row{info, OpSemantics{}};
}

// The slot costs in vs_2_x, ps_2_x, vs_3_0, ps_3_0 (in that order).
using Later = std::array<int8_t, 4>;
constexpr Row later(Row r, Later cols) {
  r.info.slots[profile_index(Profile::vs_2_x)] = cols[0];
  r.info.slots[profile_index(Profile::ps_2_x)] = cols[1];
  r.info.slots[profile_index(Profile::vs_3_0)] = cols[2];
  r.info.slots[profile_index(Profile::ps_3_0)] = cols[3];
  return r;
}

// Semantic columns, applied to a row: row(...) then these (each returns the amended row).
constexpr Row writes(Row r, uint8_t mask) {
  for (uint8_t& w : r.sem.writes) w = mask;
  return r;
}
constexpr Row writes_in_vs11(Row r, uint8_t mask) {
  r.sem.writes[profile_index(Profile::vs_1_1)] = mask;
  return r;
}
constexpr Row lanes(Row r, LaneRule rule) {
  r.sem.lanes = rule;
  return r;
}
constexpr Row fixed(Row r, uint8_t src_lanes) {
  r.sem.lanes = LaneRule::Fixed;
  r.sem.src_lanes = src_lanes;
  return r;
}
// Matrix macro: `rows` rows of `columns` lanes each, one result component per row.
constexpr Row matrix(Row r, uint8_t columns, uint8_t rows) {
  r.sem.matrix_rows = rows;
  r = fixed(r, columns == 4 ? 0xF : 0x7);
  return writes(r, static_cast<uint8_t>((1u << rows) - 1));
}
constexpr Row samples(Row r) {
  r.sem.samples = true;
  return r;
}
constexpr Row implicit(Row r, uint16_t flags) {
  r.sem.implicit = static_cast<uint16_t>(r.sem.implicit | flags);
  return r;
}
// ps_1_1..1_3 texture-address rows: three coordinate lanes from the source, TC(m) implied.
constexpr Row address(Row r) {
  return implicit(fixed(r, 0x7), kReadsTexCoord);
}
// A pad row of a texm3x2 / texm3x3 product (`rows` 2 or 3): it writes nothing readable.
constexpr Row pad_row(Row r, uint8_t rows) {
  r = writes(address(r), 0);
  r.sem.texm_rows = rows;
  r.sem.texm_pad = true;
  return r;
}
// The second or third row of a texm3x2 / texm3x3 product.
constexpr Row final_row(Row r, uint8_t rows) {
  r = implicit(address(r), kReadsPadRows);
  r.sem.texm_rows = rows;
  return r;
}

constexpr auto A = OpClass::Arith;
constexpr auto T = OpClass::Texture;
constexpr auto F = OpClass::Flow;
constexpr auto D = OpClass::Decl;
constexpr S none{no, no, no, no, no, no, no};
constexpr K V = K::Vector;
constexpr K Sc = K::Scalar;

// clang-format off
constexpr Row kRows[] = {
  //  opcode              mnemonic       code  class dst  sources              vs11 vs20 p11 p12 p13 p14 p20
  row(Opcode::Nop,      "nop",         0x00, A, false, {},                 {1,  1,  0,  0,  0,  0,  1},  "no operation"),
  row(Opcode::Mov,      "mov",         0x01, A, true,  {V},                {1,  1,  1,  1,  1,  1,  1},  "d = s0"),
  row(Opcode::Add,      "add",         0x02, A, true,  {V, V},             {1,  1,  1,  1,  1,  1,  1},  "d = s0 + s1"),
  row(Opcode::Sub,      "sub",         0x03, A, true,  {V, V},             {1,  1,  1,  1,  1,  1,  1},  "d = s0 - s1"),
  row(Opcode::Mad,      "mad",         0x04, A, true,  {V, V, V},          {1,  1,  1,  1,  1,  1,  1},  "d = s0 * s1 + s2"),
  row(Opcode::Mul,      "mul",         0x05, A, true,  {V, V},             {1,  1,  1,  1,  1,  1,  1},  "d = s0 * s1"),
  row(Opcode::Rcp,      "rcp",         0x06, A, true,  {Sc},               {1,  1, no, no, no, no,  1},  "d = 1 / s0 (scalar)"),
  row(Opcode::Rsq,      "rsq",         0x07, A, true,  {Sc},               {1,  1, no, no, no, no,  1},  "d = 1 / sqrt(|s0|) (scalar)"),
  fixed(row(Opcode::Dp3,      "dp3",         0x08, A, true,  {V, V},             {1,  1,  1,  1,  1,  1,  1},  "d = dot3(s0, s1)"), 0x7),
  fixed(row(Opcode::Dp4,      "dp4",         0x09, A, true,  {V, V},             {1,  1, no,  2,  2,  1,  1},  "d = dot4(s0, s1)"), 0xF),
  row(Opcode::Min,      "min",         0x0A, A, true,  {V, V},             {1,  1, no, no, no, no,  1},  "d = (s0 < s1) ? s0 : s1"),
  row(Opcode::Max,      "max",         0x0B, A, true,  {V, V},             {1,  1, no, no, no, no,  1},  "d = (s0 >= s1) ? s0 : s1"),
  row(Opcode::Slt,      "slt",         0x0C, A, true,  {V, V},             {1,  1, no, no, no, no, no},  "d = (s0 < s1) ? 1 : 0"),
  row(Opcode::Sge,      "sge",         0x0D, A, true,  {V, V},             {1,  1, no, no, no, no, no},  "d = (s0 >= s1) ? 1 : 0"),
  row(Opcode::Exp,      "exp",         0x0E, A, true,  {Sc},               {10, 1, no, no, no, no,  1},  "d = 2^s0 (full precision)"),
  row(Opcode::Log,      "log",         0x0F, A, true,  {Sc},               {10, 1, no, no, no, no,  1},  "d = log2(|s0|) (full precision)"),
  lanes(row(Opcode::Lit,      "lit",         0x10, A, true,  {V},                {1,  3, no, no, no, no, no},  "lighting coefficients"), LaneRule::Lit),
  lanes(row(Opcode::Dst,      "dst",         0x11, A, true,  {V, V},             {1,  1, no, no, no, no, no},  "distance vector"), LaneRule::Dst),
  row(Opcode::Lrp,      "lrp",         0x12, A, true,  {V, V, V},          {no, 2,  1,  1,  1,  1,  2},  "d = s2 + s0 * (s1 - s2)"),
  writes_in_vs11(row(Opcode::Frc,      "frc",         0x13, A, true,  {V},                {3,  1, no, no, no, no,  1},  "d = s0 - floor(s0)"), 0x3),
  matrix(row(Opcode::M4x4,     "m4x4",        0x14, A, true,  {V, K::Matrix},     {4,  4, no, no, no, no,  4},  "4x4 matrix product"), 4, 4),
  matrix(row(Opcode::M4x3,     "m4x3",        0x15, A, true,  {V, K::Matrix},     {3,  3, no, no, no, no,  3},  "4x3 matrix product"), 4, 3),
  matrix(row(Opcode::M3x4,     "m3x4",        0x16, A, true,  {V, K::Matrix},     {4,  4, no, no, no, no,  4},  "3x4 matrix product"), 3, 4),
  matrix(row(Opcode::M3x3,     "m3x3",        0x17, A, true,  {V, K::Matrix},     {3,  3, no, no, no, no,  3},  "3x3 matrix product"), 3, 3),
  matrix(row(Opcode::M3x2,     "m3x2",        0x18, A, true,  {V, K::Matrix},     {2,  2, no, no, no, no,  2},  "3x2 matrix product"), 3, 2),
  row(Opcode::Pow,      "pow",         0x20, A, true,  {Sc, Sc},           {no, 3, no, no, no, no,  3},  "d = |s0|^s1 (scalar)"),
  writes(lanes(row(Opcode::Crs,      "crs",         0x21, A, true,  {V, V},             {no, 2, no, no, no, no,  2},  "cross product"), LaneRule::Cross), 0x7),
  lanes(row(Opcode::Sgn,      "sgn",         0x22, A, true,  {V, K::Temp, K::Temp}, {no, 3, no, no, no, no, no}, "sign (two scratch temps)"), LaneRule::FirstOnly),
  row(Opcode::Abs,      "abs",         0x23, A, true,  {V},                {no, 1, no, no, no, no,  1},  "d = |s0|"),
  lanes(row(Opcode::Nrm,      "nrm",         0x24, A, true,  {V},                {no, 3, no, no, no, no,  3},  "normalize (3 components)"), LaneRule::Normalize),
  writes(row(Opcode::SinCos,   "sincos",      0x25, A, true,  {Sc, K::Const, K::Const}, {no, 8, no, no, no, no, 8}, "d.x = cos, d.y = sin"), 0x3),
  implicit(row(Opcode::Mova,     "mova",        0x2E, A, true,  {V},                {no, 1, no, no, no, no, no},  "a0 = round(s0)"), kWritesAddress),
  row(Opcode::Expp,     "expp",        0x4E, A, true,  {Sc},               {1,  1, no, no, no, no, no},  "partial-precision 2^s0"),
  row(Opcode::Logp,     "logp",        0x4F, A, true,  {Sc},               {1,  1, no, no, no, no, no},  "partial-precision log2(|s0|)"),
  row(Opcode::Cnd,      "cnd",         0x50, A, true,  {V, V, V},          {no, no, 1,  1,  1,  1, no},  "d = (s0 > 0.5) ? s1 : s2"),
  row(Opcode::Cmp,      "cmp",         0x58, A, true,  {V, V, V},          {no, no, no, 2,  2,  1,  1},  "d = (s0 >= 0) ? s1 : s2"),
  implicit(writes(fixed(row(Opcode::Bem,      "bem",         0x59, A, true,  {V, V},             {no, no, no, no, no, 2, no},  "bump environment map"), 0x3), 0x3), kBumpMatrix),
  fixed(row(Opcode::Dp2Add,   "dp2add",      0x5A, A, true,  {V, V, Sc},         {no, no, no, no, no, no, 2},  "d = dot2(s0, s1) + s2"), 0x3),

  row(Opcode::Call,     "call",        0x19, F, false, {K::Label},         {no, 2, no, no, no, no, no},  "call subroutine"),
  row(Opcode::CallNz,   "callnz",      0x1A, F, false, {K::Label, K::Bool}, {no, 3, no, no, no, no, no}, "call if bool"),
  implicit(row(Opcode::Loop,     "loop",        0x1B, F, false, {K::LoopReg, K::Int}, {no, 3, no, no, no, no, no}, "loop aL over i#"), kWritesLoopCounter),
  row(Opcode::Ret,      "ret",         0x1C, F, false, {},                 {no, 1, no, no, no, no, no},  "return"),
  row(Opcode::EndLoop,  "endloop",     0x1D, F, false, {},                 {no, 2, no, no, no, no, no},  "end of loop"),
  row(Opcode::Label,    "label",       0x1E, F, false, {K::Label},         {no, 0, no, no, no, no, no},  "subroutine label"),
  row(Opcode::Rep,      "rep",         0x26, F, false, {K::Int},           {no, 3, no, no, no, no, no},  "repeat i#.x times"),
  row(Opcode::EndRep,   "endrep",      0x27, F, false, {},                 {no, 2, no, no, no, no, no},  "end of rep"),
  row(Opcode::If,       "if",          0x28, F, false, {K::Bool},          {no, 3, no, no, no, no, no},  "if bool"),
  row(Opcode::Else,     "else",        0x2A, F, false, {},                 {no, 1, no, no, no, no, no},  "else"),
  row(Opcode::EndIf,    "endif",       0x2B, F, false, {},                 {no, 1, no, no, no, no, no},  "end of if"),
  row(Opcode::Phase,    "phase",       0xFFFD, F, false, {},               {no, no, no, no, no, 0, no},  "ps_1_4 phase marker"),

  samples(implicit(row(Opcode::Tex,      "tex",         0x42, T, true,  {},                 {no, no, 1,  1,  1, no, no},  "t(m) = sample(m, TC(m))"), kReadsTexCoord)),
  samples(fixed(row(Opcode::TexLd14,  "texld",       0x42, T, true,  {V},                {no, no, no, no, no, 1, no},  "r(m) = sample(m, src)"), 0x7)),
  samples(lanes(row(Opcode::TexLd,    "texld",       0x42, T, true,  {V, K::Sampler},    {no, no, no, no, no, no, 1},  "d = sample(s, src.xy[z])"), LaneRule::Coordinate)),
  samples(lanes(row(Opcode::TexLdP,   "texldp",      0x42, T, true,  {V, K::Sampler},    {no, no, no, no, no, no, 1},  "d = sample(s, src / src.w)", 1), LaneRule::CoordinateW)),
  samples(lanes(row(Opcode::TexLdB,   "texldb",      0x42, T, true,  {V, K::Sampler},    {no, no, no, no, no, no, 1},  "d = sample with lod bias src.w", 2), LaneRule::CoordinateW)),
  implicit(row(Opcode::TexCoord, "texcoord",    0x40, T, true,  {},                 {no, no, 1,  1,  1, no, no},  "t(m) = saturate(TC(m))"), kReadsTexCoord),
  writes(fixed(row(Opcode::TexCrd,   "texcrd",      0x40, T, true,  {V},                {no, no, no, no, no, 1, no},  "r = texture coordinates"), 0x7), 0x7),
  writes(implicit(row(Opcode::TexKill,  "texkill",     0x41, T, true,  {},                 {no, no, 1,  1,  1,  1,  1},  "discard if any component < 0"), kReadsTexCoord | kReadsOperand | kDiscards), 0),
  samples(implicit(fixed(row(Opcode::TexBem,   "texbem",      0x43, T, true,  {V},                {no, no, 1,  1,  1, no, no},  "bump-mapped sample"), 0x3), kReadsTexCoord | kBumpMatrix)),
  samples(implicit(fixed(row(Opcode::TexBemL,  "texbeml",     0x44, T, true,  {V},                {no, no, 1,  1,  1, no, no},  "bump-mapped sample with luminance", 0, 1), 0x7), kReadsTexCoord | kBumpMatrix)),
  samples(fixed(row(Opcode::TexReg2Ar, "texreg2ar",  0x45, T, true,  {V},                {no, no, 1,  1,  1, no, no},  "sample at (src.a, src.r)"), 0x9)),
  samples(fixed(row(Opcode::TexReg2Gb, "texreg2gb",  0x46, T, true,  {V},                {no, no, 1,  1,  1, no, no},  "sample at (src.g, src.b)"), 0x6)),
  samples(fixed(row(Opcode::TexReg2Rgb, "texreg2rgb", 0x52, T, true, {V},                {no, no, no, 1,  1, no, no},  "sample at src.rgb"), 0x7)),
  pad_row(row(Opcode::TexM3x2Pad, "texm3x2pad", 0x47, T, true, {V},                {no, no, 1,  1,  1, no, no},  "first row of a 3x2 product"), 2),
  samples(final_row(row(Opcode::TexM3x2Tex, "texm3x2tex", 0x48, T, true, {V},                {no, no, 1,  1,  1, no, no},  "second row, then sample"), 2)),
  writes(implicit(final_row(row(Opcode::TexM3x2Depth, "texm3x2depth", 0x54, T, true, {V},            {no, no, no, no, 1, no, no},  "second row, then depth"), 2), kWritesDepth), 0),
  pad_row(row(Opcode::TexM3x3Pad, "texm3x3pad", 0x49, T, true, {V},                {no, no, 1,  1,  1, no, no},  "row of a 3x3 product"), 3),
  samples(final_row(row(Opcode::TexM3x3Tex, "texm3x3tex", 0x4A, T, true, {V},                {no, no, 1,  1,  1, no, no},  "third row, then sample"), 3)),
  final_row(row(Opcode::TexM3x3,  "texm3x3",     0x56, T, true,  {V},                {no, no, no, 1,  1, no, no},  "third row, result as colour"), 3),
  samples(final_row(row(Opcode::TexM3x3Spec, "texm3x3spec", 0x4C, T, true, {V, K::Const},    {no, no, 1,  1,  1, no, no},  "reflect constant eye, sample"), 3)),
  samples(implicit(final_row(row(Opcode::TexM3x3VSpec, "texm3x3vspec", 0x4D, T, true, {V},            {no, no, 1,  1,  1, no, no},  "reflect interpolated eye, sample"), 3), kReadsEyeFromRows)),
  address(row(Opcode::TexDp3,   "texdp3",      0x55, T, true,  {V},                {no, no, no, 1,  1, no, no},  "t(m) = dot(TC(m), src)")),
  samples(address(row(Opcode::TexDp3Tex, "texdp3tex",  0x53, T, true,  {V},                {no, no, no, 1,  1, no, no},  "1D sample at dot(TC(m), src)"))),
  writes(implicit(row(Opcode::TexDepth, "texdepth",    0x57, T, true,  {},                 {no, no, no, no, no, 1, no},  "depth = r5.r / r5.g"), kReadsOperand | kWritesDepth), 0),

  row(Opcode::Dcl,      "dcl",         0x1F, D, true,  {},                 {0,  0, no, no, no, no,  0},  "declaration"),
  row(Opcode::Def,      "def",         0x51, D, true,  {},                 {0,  0,  0,  0,  0,  0,  0},  "float constant"),
  row(Opcode::DefI,     "defi",        0x30, D, true,  {},                 {no, 0, no, no, no, no, no},  "integer constant"),
  row(Opcode::DefB,     "defb",        0x2F, D, true,  {},                 {no, 0, no, no, no, no, no},  "boolean constant"),

  //                                                                                          vs2x p2x vs30 p30
  writes(later(row(Opcode::SinCos3,  "sincos",      0x25, A, true,  {Sc},     none, "d.x = cos, d.y = sin (one source)"), {no, no, 8, 8}), 0x3),
  later(row(Opcode::Break,    "break",       0x2C, F, false, {},       none, "leave the loop or rep"),                {1,  1,  1,  1}),
  later(row(Opcode::BreakGt,  "break_gt",    0x2D, F, false, {V, V},   none, "break if s0 > s1", 1),                 {3,  3,  3,  3}),
  later(row(Opcode::BreakEq,  "break_eq",    0x2D, F, false, {V, V},   none, "break if s0 == s1", 2),                {3,  3,  3,  3}),
  later(row(Opcode::BreakGe,  "break_ge",    0x2D, F, false, {V, V},   none, "break if s0 >= s1", 3),                {3,  3,  3,  3}),
  later(row(Opcode::BreakLt,  "break_lt",    0x2D, F, false, {V, V},   none, "break if s0 < s1", 4),                 {3,  3,  3,  3}),
  later(row(Opcode::BreakNe,  "break_ne",    0x2D, F, false, {V, V},   none, "break if s0 != s1", 5),                {3,  3,  3,  3}),
  later(row(Opcode::BreakLe,  "break_le",    0x2D, F, false, {V, V},   none, "break if s0 <= s1", 6),                {3,  3,  3,  3}),
  later(row(Opcode::BreakP,   "breakp",      0x60, F, false, {K::Predicate}, none, "break if the predicate"),        {3,  3,  3,  3}),
  later(row(Opcode::IfGt,     "if_gt",       0x29, F, false, {V, V},   none, "if s0 > s1", 1),                       {3,  3,  3,  3}),
  later(row(Opcode::IfEq,     "if_eq",       0x29, F, false, {V, V},   none, "if s0 == s1", 2),                      {3,  3,  3,  3}),
  later(row(Opcode::IfGe,     "if_ge",       0x29, F, false, {V, V},   none, "if s0 >= s1", 3),                      {3,  3,  3,  3}),
  later(row(Opcode::IfLt,     "if_lt",       0x29, F, false, {V, V},   none, "if s0 < s1", 4),                       {3,  3,  3,  3}),
  later(row(Opcode::IfNe,     "if_ne",       0x29, F, false, {V, V},   none, "if s0 != s1", 5),                      {3,  3,  3,  3}),
  later(row(Opcode::IfLe,     "if_le",       0x29, F, false, {V, V},   none, "if s0 <= s1", 6),                      {3,  3,  3,  3}),
  later(row(Opcode::SetpGt,   "setp_gt",     0x5E, A, true,  {V, V},   none, "p0 = s0 > s1 per component", 1),       {1,  1,  1,  1}),
  later(row(Opcode::SetpEq,   "setp_eq",     0x5E, A, true,  {V, V},   none, "p0 = s0 == s1 per component", 2),      {1,  1,  1,  1}),
  later(row(Opcode::SetpGe,   "setp_ge",     0x5E, A, true,  {V, V},   none, "p0 = s0 >= s1 per component", 3),      {1,  1,  1,  1}),
  later(row(Opcode::SetpLt,   "setp_lt",     0x5E, A, true,  {V, V},   none, "p0 = s0 < s1 per component", 4),       {1,  1,  1,  1}),
  later(row(Opcode::SetpNe,   "setp_ne",     0x5E, A, true,  {V, V},   none, "p0 = s0 != s1 per component", 5),      {1,  1,  1,  1}),
  later(row(Opcode::SetpLe,   "setp_le",     0x5E, A, true,  {V, V},   none, "p0 = s0 <= s1 per component", 6),      {1,  1,  1,  1}),
  samples(lanes(later(row(Opcode::TexLdL,   "texldl",      0x5F, T, true,  {V, K::Sampler}, none, "d = sample at lod src.w"), {no, no, 2, 2}), LaneRule::CoordinateW)),
  samples(lanes(later(row(Opcode::TexLdD,   "texldd",      0x5D, T, true,  {V, K::Sampler, V, V}, none, "d = sample with gradients s2, s3"), {no, 3, no, 3}), LaneRule::Coordinate)),
  later(row(Opcode::Dsx,      "dsx",         0x5B, A, true,  {V},      none, "d = rate of change along x"),           {no, 2, no, 2}),
  later(row(Opcode::Dsy,      "dsy",         0x5C, A, true,  {V},      none, "d = rate of change along y"),           {no, 2, no, 2}),
};
// clang-format on

static_assert(std::size(kRows) == kOpcodeCount, "one row per Opcode");

// Rows of the first seven profiles whose 2.x / 3.0 columns differ from vs_2_0 / ps_2_0:
// ps_2_x and ps_3_0 have static flow control (loop and aL in ps_3_0 only), i# and b#;
// 3.0's sincos takes one source (SinCos3).
struct LaterColumns {
  Opcode op;
  Later cols; // vs_2_x ps_2_x vs_3_0 ps_3_0
};
// clang-format off
constexpr LaterColumns kLaterColumns[] = {
  {Opcode::SinCos,  {8,  8, no, no}},
  {Opcode::Call,    {2,  2,  2,  2}},
  {Opcode::CallNz,  {3,  3,  3,  3}},
  {Opcode::Loop,    {3, no,  3,  3}},
  {Opcode::Ret,     {1,  1,  1,  1}},
  {Opcode::EndLoop, {2, no,  2,  2}},
  {Opcode::Label,   {0,  0,  0,  0}},
  {Opcode::Rep,     {3,  3,  3,  3}},
  {Opcode::EndRep,  {2,  2,  2,  2}},
  {Opcode::If,      {3,  3,  3,  3}},
  {Opcode::Else,    {1,  1,  1,  1}},
  {Opcode::EndIf,   {1,  1,  1,  1}},
  {Opcode::DefI,    {0,  0,  0,  0}},
  {Opcode::DefB,    {0,  0,  0,  0}},
};
// clang-format on

constexpr std::array<Row, kOpcodeCount> with_later_columns() {
  std::array<Row, kOpcodeCount> out{};
  for (size_t i = 0; i < kOpcodeCount; ++i) out[i] = kRows[i];
  for (const LaterColumns& l : kLaterColumns) {
    Row& r = out[static_cast<size_t>(l.op)];
    r = later(r, l.cols);
  }
  return out;
}
constexpr auto kAllRows = with_later_columns();

template <class T, class Pick> constexpr std::array<T, kOpcodeCount> column(Pick pick) {
  std::array<T, kOpcodeCount> out{};
  for (size_t i = 0; i < kOpcodeCount; ++i) out[i] = pick(kAllRows[i]);
  return out;
}
constexpr auto kTable = column<OpInfo>([](const Row& r) { return r.info; });
// By opcode value (the rows are in Opcode order: checked below).
constexpr auto kSemantics = column<OpSemantics>([](const Row& r) { return r.sem; });
constexpr bool rows_in_opcode_order() {
  for (size_t i = 0; i < kOpcodeCount; ++i)
    if (static_cast<size_t>(kRows[i].info.op) != i) return false;
  return true;
}
static_assert(rows_in_opcode_order(), "kRows lists the opcodes in enum order");

struct Index {
  std::array<const OpInfo*, kOpcodeCount> by_op{};
  std::map<std::string, std::vector<const OpInfo*>, std::less<>> by_mnemonic;
  Index() {
    for (const OpInfo& info : kTable) {
      by_op[static_cast<int>(info.op)] = &info;
      by_mnemonic[std::string(info.mnemonic)].push_back(&info);
    }
  }
};

const Index& index() {
  static const Index idx;
  return idx;
}

} // namespace

std::span<const OpInfo> opcode_table() {
  return kTable;
}

const OpSemantics& op_semantics(Opcode op) {
  return kSemantics[static_cast<size_t>(op)];
}

const OpInfo& op_info(Opcode op) {
  return *index().by_op[static_cast<int>(op)];
}

std::span<const OpInfo* const> rows_for_mnemonic(std::string_view mnemonic) {
  const auto& m = index().by_mnemonic;
  auto it = m.find(mnemonic);
  if (it == m.end()) return {};
  return it->second;
}

const OpInfo* find_opcode(std::string_view mnemonic, Profile p) {
  auto rows = rows_for_mnemonic(mnemonic);
  if (rows.empty()) return nullptr;
  for (const OpInfo* r : rows)
    if (legal_in(*r, p)) return r;
  return rows.front();
}

const OpInfo* find_opcode_by_code(uint16_t code, uint8_t control, Profile p) {
  for (const OpInfo& info : kTable)
    if (info.code == code && info.control == control && legal_in(info, p)) return &info;
  return nullptr;
}

} // namespace tierlift::ir
