// The validator also sees programs that did not come from the parser (bytecode, tools): any
// combination of opcodes, register files, indices, masks, swizzles and modifiers must give
// diagnostics, never a crash or a hang (this suite runs under ASan/UBSan in CI).
#include <gtest/gtest.h>

#include <random>

#include "tierlift/assembly/validator.h"

using namespace tierlift;

namespace {

uint32_t R(std::mt19937& g) {
  return static_cast<uint32_t>(g());
}

ir::SrcOperand random_src(std::mt19937& rng) {
  ir::SrcOperand s;
  s.file = static_cast<ir::RegFile>(R(rng) % 15);
  s.index = R(rng) % 4 == 0 ? static_cast<uint32_t>(R(rng)) : R(rng) % 40;
  s.swizzle = static_cast<uint8_t>(R(rng));
  s.mod = static_cast<ir::SrcMod>(R(rng) % 14);
  if (R(rng) % 8 == 0)
    s.rel = ir::RelAddr{R(rng) % 2 ? ir::RegFile::Addr : ir::RegFile::Loop,
                        static_cast<uint8_t>(R(rng) % 4),
                        {},
                        std::nullopt};
  s.loc = {0, 1 + R(rng) % 50, 1 + R(rng) % 30, 2};
  return s;
}

ir::Program random_program(std::mt19937& rng) {
  ir::Program p;
  p.profile = ir::kAllProfiles[R(rng) % ir::kProfileCount];
  uint32_t seq = 0;
  int n = static_cast<int>(R(rng) % 40);
  for (int i = 0; i < n; ++i) {
    ir::Instruction ins;
    ins.op = static_cast<ir::Opcode>(R(rng) % ir::kOpcodeCount);
    ins.coissue = R(rng) % 6 == 0;
    ins.mods.sat = R(rng) % 5 == 0;
    ins.mods.pp = R(rng) % 7 == 0;
    ins.mods.shift = static_cast<int8_t>(static_cast<int>(R(rng) % 9) - 4);
    if (R(rng) % 5) {
      ir::DstOperand d;
      d.file = static_cast<ir::RegFile>(R(rng) % 15);
      d.index = R(rng) % 4 == 0 ? static_cast<uint32_t>(R(rng)) : R(rng) % 40;
      d.mask = static_cast<uint8_t>(R(rng) % 17);
      ins.dst = d;
    }
    int ns = static_cast<int>(R(rng) % 5);
    for (int k = 0; k < ns; ++k) ins.src.push_back(random_src(rng));
    ins.loc = {0, static_cast<uint32_t>(i + 2), 1, 3};
    ins.seq = seq++;
    p.code.push_back(ins);
  }
  for (int i = 0; i < static_cast<int>(R(rng) % 4); ++i) {
    ir::Declaration d;
    d.reg.file = static_cast<ir::RegFile>(R(rng) % 15);
    d.reg.index = R(rng) % 20;
    d.reg.mask = static_cast<uint8_t>(R(rng) % 16);
    d.sampler_type = static_cast<ir::SamplerType>(R(rng) % 5);
    d.seq = static_cast<uint32_t>(R(rng) % (seq + 1));
    p.decls.push_back(d);
  }
  for (int i = 0; i < static_cast<int>(R(rng) % 4); ++i) {
    ir::ConstDef d;
    d.file = R(rng) % 3 == 0 ? ir::RegFile::ConstInt : ir::RegFile::Const;
    d.index = R(rng) % 300;
    for (auto& r : d.raw) r = static_cast<uint32_t>(R(rng));
    d.seq = static_cast<uint32_t>(R(rng) % (seq + 1));
    p.defs.push_back(d);
  }
  return p;
}

TEST(ValidatorRobustness, RandomProgramsAgainstEveryProfile) {
  std::mt19937 rng(20261122);
  size_t errors = 0;
  for (int i = 0; i < 500; ++i) {
    ir::Program p = random_program(rng);
    for (ir::Profile target : ir::kAllProfiles) {
      ir::DiagnosticSink sink;
      bool ok = assembly::validate(p, target, sink);
      EXPECT_EQ(ok, !sink.has_errors());
      errors += sink.error_count();
    }
  }
  EXPECT_GT(errors, 0u);
}

} // namespace
