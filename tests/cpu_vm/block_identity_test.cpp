// The block executor (pixel_block.h) against the per-pixel VM, the reference: on every pixel
// listing we hold (listings/ and, when present, the shared corpus), on listings written here
// to reach every instruction and modifier the block path takes, in each conventions mode,
// with random inputs, constants and a texture unit whose result depends on the coordinate,
// every lane must come out bit for bit as ShaderVM::run_pixel computes that pixel.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <vector>

#include "skip_policy.h"
#include "tierlift/cpu/pixel_block.h"
#include "vm_test_util.h"

using namespace vmtest;
using tierlift::cpu::kBlockLanes;
using tierlift::cpu::PixelBlockInput;
using tierlift::cpu::PixelBlockOutput;
using tierlift::cpu::PixelBlockVM;
namespace fs = std::filesystem;
namespace ir = tierlift::ir;

namespace {

// A texture whose value is a nonlinear function of all four coordinates and the stage (so a
// wrong coordinate, stage or lane shows), with projected stages to reach D3DTTFF_PROJECTED.
class MixTextures final : public TextureUnit {
public:
  Vec4 sample(uint32_t stage, const Vec4& c, float bias) const override {
    const float s = static_cast<float>(stage);
    return {c[0] * 0.75f + c[1], c[1] - c[2] * 0.5f + s, c[3] * c[0] - bias,
            std::fabs(c[2]) + 0.25f};
  }
  StageState stage_state(uint32_t stage) const override {
    StageState st;
    st.projected = stage % 3 == 1;
    st.bumpenv_mat = {0.5f, -0.25f, 0.125f, 1.5f};
    return st;
  }
};

// Denormals of both signs (NUMERICS.md rule 13: lavapipe's mode flushes them in every
// operation, the exact mode keeps them): the smallest, the largest, some between, and the
// zeros and smallest normals beside them.
const float kDenormals[] = {1e-40f,           -1e-40f,           0x1p-149f, -0x1p-149f,
                            0x1.fffffcp-127f, -0x1.fffffcp-127f, 0x1p-127f, -0x1p-127f,
                            0x1p-126f,        -0x1p-126f,        0.0f,      -0.0f};

// A texture unit that answers denormals of both signs (and the coordinate's own bits in w): a
// different denormal for a different coordinate, so a wrong lane still shows.
class DenormalTextures final : public TextureUnit {
public:
  Vec4 sample(uint32_t stage, const Vec4& c, float bias) const override {
    const float s = static_cast<float>(stage + 1);
    return {c[0] * 0x1p-128f, -c[1] * s * 0x1p-129f, c[2] > 0.0f ? 1e-40f : -1e-40f,
            c[3] + bias * 0x1p-130f};
  }
  StageState stage_state(uint32_t stage) const override {
    StageState st;
    st.projected = stage % 3 == 1;
    return st;
  }
};

class Random {
public:
  explicit Random(uint32_t seed, bool denormals = false) : rng_(seed), denormals_(denormals) {}
  // Mostly ordinary values, sometimes the ones numeric rules treat specially; with
  // `denormals`, half of them denormals or the values beside them.
  float value() {
    static const float kSpecial[] = {0.0f,    -0.0f,   1.0f,     -1.0f,       0.5f,
                                     nan_f(), inf_f(), -inf_f(), 1e-40f,      -1e-40f,
                                     1e30f,   -1e30f,  2.0f,     0.49999997f, 255.0f / 256.0f};
    std::uniform_int_distribution<int> pick(0, 9);
    if (denormals_ && pick(rng_) < 5) {
      std::uniform_int_distribution<size_t> k(0, std::size(kDenormals) - 1);
      return kDenormals[k(rng_)];
    }
    if (pick(rng_) == 0) {
      std::uniform_int_distribution<size_t> k(0, std::size(kSpecial) - 1);
      return kSpecial[k(rng_)];
    }
    std::uniform_real_distribution<float> u(-2.0f, 2.0f);
    return u(rng_);
  }
  Vec4 vec() { return {value(), value(), value(), value()}; }

private:
  std::mt19937 rng_;
  bool denormals_;
};

bool same_bits(float a, float b) {
  return (std::isnan(a) && std::isnan(b)) || bits(a) == bits(b); // NaN payloads may differ
}

// Runs `program` both ways on `rounds` random blocks; returns false when the block path
// refuses it. Failures are reported with the lane's inputs. `denormals`: inputs, constants and
// texels are half denormals (DenormalTextures instead of MixTextures).
bool compare(const ir::Program& program, const ir::Conventions& conv, int rounds, uint32_t seed,
             const std::string& name, bool denormals = false) {
  Random rnd(seed, denormals);
  ConstantBank bank;
  for (int i = 0; i < 32; ++i) bank.f.push_back(rnd.vec());
  std::unique_ptr<PixelBlockVM> block = PixelBlockVM::create(program, conv, bank);
  if (!block) return false;
  ShaderVM vm = vm_of(program, conv);
  MixTextures mix;
  DenormalTextures tiny;
  const TextureUnit& tex = denormals ? static_cast<const TextureUnit&>(tiny) : mix;
  auto scratch = block->make_scratch();
  PixelBlockInput in;
  PixelBlockOutput out;
  for (int round = 0; round < rounds; ++round) {
    std::vector<PixelInput> pixels(kBlockLanes);
    in.count = kBlockLanes - round % 3; // full and partial blocks
    for (int l = 0; l < kBlockLanes; ++l) {
      PixelInput& p = pixels[static_cast<size_t>(l)];
      for (auto& c : p.color) c = rnd.vec();
      for (auto& t : p.tex) t = rnd.vec();
      for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 4; ++c) in.color[r].c[c][l] = p.color[r][c];
      for (int r = 0; r < 8; ++r)
        for (int c = 0; c < 4; ++c) in.tex[r].c[c][l] = p.tex[r][c];
    }
    block->run(in, tex, out, *scratch);
    for (int l = 0; l < in.count; ++l) {
      const PixelOutput ref = vm.run_pixel(pixels[static_cast<size_t>(l)], bank, tex);
      SCOPED_TRACE(name + " round " + std::to_string(round) + " lane " + std::to_string(l));
      // One report per program: the first lane that differs.
      if (out.discarded[static_cast<size_t>(l)] != ref.discarded) {
        ADD_FAILURE() << "discarded: block " << out.discarded[static_cast<size_t>(l)]
                      << ", per-pixel " << ref.discarded;
        return true;
      }
      if (ref.discarded) continue;
      for (int c = 0; c < 4; ++c)
        if (!same_bits(out.color->c[c][l], ref.color[0][c])) {
          ADD_FAILURE() << "component " << c << ": block " << out.color->c[c][l] << ", per-pixel "
                        << ref.color[0][c];
          return true;
        }
    }
  }
  return true;
}

std::vector<ir::Conventions> conventions_modes() {
  std::vector<ir::Conventions> modes(4);
  modes[1].rounding = ir::Rounding::Exact;
  modes[2].ps1x_max_value = 8.0f; // ps_1_4-class range
  modes[3].ps1x_fixed_bits = 8;   // fixed-point emulation
  return modes;
}

struct FolderResult {
  int taken = 0, refused = 0;
  std::vector<std::string> refused_names;
};

void run_folder(const fs::path& dir, FolderResult& r) {
  if (!fs::exists(dir)) return;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".psh") continue;
    std::ifstream f(e.path());
    std::stringstream ss;
    ss << f.rdbuf();
    auto parsed = tierlift::assembly::parse_text(ss.str(), e.path().string());
    if (!parsed.program) continue;
    ir::DiagnosticSink d;
    if (!tierlift::assembly::validate(*parsed.program, d)) continue;
    bool taken = false;
    uint32_t seed = 1;
    for (const ir::Conventions& conv : conventions_modes())
      taken = compare(*parsed.program, conv, 24, seed++, e.path().filename().string()) || taken;
    (taken ? r.taken : r.refused)++;
    if (!taken) r.refused_names.push_back(e.path().filename().string());
  }
}

} // namespace

// The glow's and the article's pixel listings must all take the block path (that is where
// the speed comes from), and agree. The one exception is tier dx9c's blur, a ps_3_0 loop:
// flow control runs on the per-pixel VM.
TEST(BlockIdentity, ListingsInTheRepository) {
  FolderResult r;
  run_folder(fs::path(TIERLIFT_SOURCE_DIR) / "listings" / "glow", r);
  run_folder(fs::path(TIERLIFT_SOURCE_DIR) / "listings" / "gpugems21", r);
  EXPECT_EQ(r.refused_names, std::vector<std::string>{"blur_loop_ps30.psh"});
  EXPECT_GE(r.taken, 9);
}

TEST(BlockIdentity, SharedCorpus) {
  fs::path corpus = fs::path(TIERLIFT_SHARED_DIR) / "corpus";
  if (!fs::exists(corpus))
    TIERLIFT_SKIP_UNLESS_REQUIRED(tierlift::test::kRequireCorpus,
                                  "no shared corpus at " + corpus.string());
  FolderResult r;
  run_folder(corpus, r);
  std::printf("corpus pixel listings: %d on the block path, %d per pixel\n", r.taken, r.refused);
  EXPECT_GE(r.taken + r.refused, 1);
}

// Listings that reach every instruction and operand form the block path has its own code for.
const char* const kEveryForm[] = {
    // ps_2_0 arithmetic, swizzles, negation, _sat, the per-lane fallback (rcp … sincos).
    "ps_2_0\ndcl t0\ndcl t1\ndcl v0\ndcl v1\ndcl_2d s0\ndcl_2d s1\n"
    "texld r0, t0, s0\ntexldp r1, t1, s1\ntexldb r2, t0, s1\n"
    "add r3, r0, -r1.yzxw\nsub r4, r3, c1\nmul r5, r4, v0\nmad_sat r6, r5, c2.wzyx, -v1\n"
    "dp3 r7.x, r6, r0\ndp4 r7.y, r6, -c3\nmin r7.z, r0.x, r1.y\nmax r7.w, r2, c4\n"
    "min r8, r0, r1\nmax r9, r1, r0.wzyx\nlrp r10, r8, r0, r1\ncmp r11, -r3, r9, r10\n"
    "abs r1, r3\nfrc r2, r4\nrcp r3.x, r5.y\nrsq r3.y, r5.z\nexp r3.z, r5.w\nlog r3.w, r5.x\n"
    "pow r4.x, r0.x, r1.y\nnrm r5.xyz, r6\ncrs r0.xyz, r5, r1\nsincos r2.xy, r7.x, c6, c7\n"
    "dp2add r4.y, r0, r1, c5.x\nmov r4.zw, r11\n"
    "add r0, r0, r1\nadd r0, r0, r2\nadd r0, r0, r3\nadd r0, r0, r4\nadd r0, r0, r5\n"
    "add r0, r0, r7\nadd r0, r0, r9\nmov oC0, r0\n",
    // Results written straight into their register (BlockStep::direct) beside the ones that
    // must go through the copy: a swizzle reading a component an earlier one of the same
    // write replaced (r1.xy = r1.yz, r0.xz = r0.zx, r2 = r2.wzyx), components the mask
    // leaves alone (r1.x into r1.yzw, r0.a into r0.rgb), a dot product onto its own source,
    // a texture read whose coordinate is its destination.
    "ps_2_0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nmov r1, r0\nmov r1.xy, r1.yzxw\n"
    "add r1.yzw, r1.x, r1\nmul r0.rgb, r0, r0.a\nmad r0.xz, r0.zxyw, c0, r0\n"
    "dp3 r1.xw, r1, r1\nmov r2, r0.wzyx\nmov r2, r2.wzyx\nmul r2, r2, -r2.yzxw\n"
    "texld r2, r2, s0\nadd r0, r0, r1\nadd r0, r0, r2\nmov oC0, r0\n",
    // ps_2_0 texkill and a coordinate read straight from t#.
    "ps_2_0\ndcl t0\ndcl t2\ndcl_2d s3\ntexkill t2\ntexld r0, t0, s3\nmul r0, r0, t2\nmov oC0, "
    "r0\n",
    // ps_1_1 texture instructions, source modifiers, shifts, co-issue.
    "ps_1_1\ntex t0\ntexcoord t1\ntex t2\ntexkill t3\n"
    "mul_x2 r0.rgb, t0_bx2, t1_bias\n+add r0.a, 1-t2.a, c0.a\n"
    "mad_d2 r1, -t1, c1, r0\ncnd r0, r0.a, r1, t2\nsub_sat r0.rgb, r0, -c2\n"
    "dp3_x4 r1, t0, t2\nlrp r0, t1, r0, r1\n",
    // ps_1_4 phases, texcrd, texld with _dw and _dz, bx2 and x2 modifiers.
    "ps_1_4\ntexcrd r0.rgb, t0\ntexld r1, t1\ntexld r2, t2_dw.xyw\n"
    "add r3.rgb, r0_bx2, r1_x2\n+mov r3.a, r1.a\nmul r4, r2, c0\nphase\ntexld r5, r3_dz\n"
    "texkill t4\nmad r0.rgb, r3, r5, r4\n+add_sat r0.a, r5.b, c1.a\n",
    // ps_1_3 cnd on r0.a, x4 shift, texcoord read back.
    "ps_1_3\ntex t0\ntex t1\ntexcoord t2\nmul_x4 r0, t0, c0\ncnd r1, r0.a, t1, t2\n"
    "add r0.rgb, r1, -r0\n+mov r0.a, t2.b\n",
    // def constants holding denormals of both signs (lavapipe's mode loads them flushed).
    "ps_2_0\ndef c8, 1e-40, -1e-40, 1.1754942e-38, -1.4e-45\ndcl t0\ndcl v0\ndcl_2d s0\n"
    "texld r0, t0, s0\nadd r1, r0, c8\nmul r2, c8.yzxw, v0\nmad r3, r0, c8, -c8.wzyx\n"
    "cmp r4, c8.y, r1, r2\nmin r5, r3, c8\nmax r6, -c8, r4\ncmp r7, -c8, r0, c8\n"
    "max r8, c8.wzyx, -r0\nrcp r9.x, c8.y\nrsq r9.y, c8.x\nlog r9.z, c8.w\nfrc r9.w, c8.y\n"
    "dp3 r10, r0, c8\ndp2add r11, r0, c8, c8.y\nlrp r1, c8, r0, r1\nadd r0, r1, r2\n"
    "add r0, r0, r3\nadd r0, r0, r4\nadd r0, r0, r5\nadd r0, r0, r6\nadd r0, r0, r7\n"
    "add r0, r0, r8\nadd r0, r0, r9\nadd r0, r0, r10\nadd_sat r0, r0, r11\nmov oC0, r0\n",
    // ps_1_1 with denormal defs through the [-1, 1] constant clamp, _bx2, _x2 and cnd.
    "ps_1_1\ndef c4, 1e-40, -1e-40, 0.5, -1.4e-45\ntex t0\ntexcoord t1\n"
    "mul_x2 r0.rgb, t0_bx2, c4\n+add r0.a, t1.a, -c4.b\nmad r1, c4, t1_bias, -t0\n"
    "cnd r0, r0.a, r1, c4\nadd r0, r0, c4\n",
    // Products with a constant factor that is ±0 in every component (the product is +0; mad
    // adds +0 to its addend, which turns a -0 addend into +0) or never zero (only the other
    // factor is tested), on either side, each result written out on its own.
    "ps_2_0\ndef c8, 0, -0, 0, -0\ndcl t0\ndcl v0\ndcl_2d s0\ntexld r0, t0, s0\n"
    "mad r1, r0, c8, -v0\nmov oC0, r1\n",
    "ps_2_0\ndef c8, 0, -0, 0, -0\ndcl t0\ndcl v0\nmad r1, c8.yzxw, t0, v0\nmov oC0, r1\n",
    "ps_2_0\ndef c8, -0, -0, 0, 0\ndcl v0\nmul r1, c8, v0\nmov oC0, r1\n",
    "ps_2_0\ndef c9, 0.5, -2, 1e30, -1e-10\ndcl t0\ndcl v0\ndcl_2d s0\ntexld r0, t0, s0\n"
    "mad r1, r0, c9, -v0\nmov oC0, r1\n",
    "ps_2_0\ndef c9, 0.5, -2, 1e30, -1e-10\ndcl t0\ndcl v0\nmul r1, c9.wzyx, v0\n"
    "mad r1, c9, t0, r1\nmov oC0, r1\n",
    "ps_2_0\ndef c9, 0.5, -2, 1e30, -1e-10\ndcl v0\nmul r1, v0, c9\nmov oC0, r1\n",
    // A constant that is zero in some components only: a product keeping the others is
    // left alone, one keeping the zero ones only is not (ir::zero_constant_products).
    "ps_2_0\ndef c8, 0, -0, 0, 1\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nmul r1, r0, c8\n"
    "mad r1.xyz, r0, c8, r1\nmov oC0, r1\n",
    // ps_1_1 and ps_1_4 (Listing 4's shape): a read weighted by a zero def is left out.
    "ps_1_1\ndef c1, 0, -0, 0, 0\ntex t0\ntex t1\ntex t2\nmul r0, t0, c0\n"
    "mad r0, t1, c1, r0\nmad r0, t2, c2, r0\n",
    "ps_1_4\ndef c1, 0, 0, -0, 0\ntexld r0, t0\ntexld r1, t1\ntexld r2, t2\n"
    "mul r0, r0, c0\nmad r0, r1, c1, r0\nmad r0, r2, c2, r0\n",
    // A texel (a denormal, with DenormalTextures) or a coordinate passed on by an
    // instruction that moves or selects bits, then scaled far up or added to a zero: the
    // operand must still be flushed in lavapipe's mode (BlockStep::clean may not be set for
    // what reads it), or the product is a normal number instead of ±0 and the sum keeps the
    // sign of the denormal instead of +0. One chain per listing, so that none hides another.
    "ps_2_0\ndef c8, 1e30, 0, -1e30, 0.5\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nmov r1, r0\n"
    "mul r2, r1, c8.x\nmov oC0, r2\n",
    "ps_2_0\ndef c8, 1e30, 0, -1e30, 0.5\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nmov r1, r0\n"
    "add r2, r1, c8.y\nmov oC0, r2\n",
    "ps_2_0\ndef c8, 1e30, 0, -1e30, 0.5\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nabs r1, r0\n"
    "mul r2, r1, c8.z\nmov oC0, r2\n",
    "ps_2_0\ndef c8, 1e30, 0, -1e30, 0.5\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\n"
    "min r1, r0, c8.y\nmul r2, r1, c8.x\nmov oC0, r2\n",
    "ps_2_0\ndef c8, 1e30, 0, -1e30, 0.5\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\n"
    "max r1, r0, -r0\nmul r2, r1, c8.x\nmov oC0, r2\n",
    "ps_2_0\ndef c8, 1e30, 0, -1e30, 0.5\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\n"
    "cmp r1, r0, r0, -r0\nmul r2, r1, c8.x\nmov oC0, r2\n",
    "ps_2_0\ndef c8, 1e30, 0, -1e30, 0.5\ndcl t0\nmov r1, t0\nmul r2, r1, c8.x\nmov oC0, r2\n",
    "ps_1_4\ndef c7, 1, 0, -1, 0.5\ntexld r0, t0\nmov r1, r0\nmul_x4 r2, r1, c7.x\n"
    "add r0, r2, c7.y\n",
};

// Every listing of kEveryForm in every conventions mode, seeds from `first_seed` on (the cases
// named `label` n); with `denormals`, inputs, constants and texels half denormals.
void compare_every_form(uint32_t first_seed, const std::string& label, bool denormals) {
  int n = 0;
  for (const char* text : kEveryForm) {
    const ir::Program program = parse(text);
    uint32_t seed = first_seed;
    for (const ir::Conventions& conv : conventions_modes()) {
      EXPECT_TRUE(compare(program, conv, 64, seed++, label + std::to_string(n), denormals))
          << "the block path refused listing " << n;
    }
    ++n;
  }
}

TEST(BlockIdentity, EveryFormTheBlockPathTakes) {
  compare_every_form(100, "listing ", false);
}

// The same listings with inputs, constants and texels that are half denormals of both signs:
// in lavapipe's mode (every operation flushes them, NUMERICS.md rule 13) and in the exact one
// (kept), the block path must agree with the per-pixel VM bit for bit.
TEST(BlockIdentity, DenormalsInInputsConstantsAndTexels) {
  compare_every_form(500, "denormal listing ", true);
}

// What the block path does not take it must refuse (the caller then runs per pixel):
// texture-address instructions and relative reads never reach it.
TEST(BlockIdentity, RefusesWhatItDoesNotRun) {
  const ir::Program bem = parse("ps_1_1\ntex t0\ntexbem t1, t0\nmov r0, t1\n");
  EXPECT_EQ(PixelBlockVM::create(bem, {}, {}), nullptr);
  const ir::Program m3 =
      parse("ps_1_1\ntex t0\ntexm3x2pad t1, t0\ntexm3x2tex t2, t0\nmov r0, t2\n");
  EXPECT_EQ(PixelBlockVM::create(m3, {}, {}), nullptr);
  const ir::Program vs = parse("vs_2_0\ndcl_position v0\nmov oPos, v0\n");
  EXPECT_EQ(PixelBlockVM::create(vs, {}, {}), nullptr);
}
