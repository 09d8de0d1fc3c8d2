// Test-only: a tiny evaluator for the subset of SPIR-V the code generator emits for vertex
// shaders (Private/Input/Output/Uniform variables, float/int/bool arithmetic, selects,
// GLSL.std.450 basics, structured branches, calls). It executes one invocation with exact
// fp32 arithmetic so tests can check emitted semantics against ir::numerics without a GPU.
#pragma once

#include <spirv/unified1/GLSL.std.450.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <vector>

#include <spirv/unified1/spirv.hpp11>

namespace tierlift::spirv_test {

class SpirvEval {
public:
  using Vec4 = std::array<float, 4>;
  explicit SpirvEval(std::vector<uint32_t> words) : w_(std::move(words)) { scan(); }

  std::map<uint32_t, Vec4> inputs;     // by Location
  std::vector<uint32_t> uniform_words; // the uniform block's bytes (pack_uniforms)
  std::map<uint32_t, Vec4> outputs;    // by Location (scalars in [0])
  Vec4 position{};
  bool killed = false;

  void run() {
    for (auto& [var, info] : vars_) {
      mem_[var] = info.init;
      if (info.sc == spv::StorageClass::Input && location_.count(var))
        for (uint32_t k = 0; k < mem_[var].size() && k < 4; ++k)
          mem_[var][k] = std::bit_cast<uint32_t>(inputs[location_[var]][k]);
      if (info.sc == spv::StorageClass::Uniform) mem_[var] = uniform_words;
    }
    call(entry_);
    for (auto& [var, info] : vars_) {
      if (info.sc != spv::StorageClass::Output) continue;
      Vec4 v{};
      for (size_t k = 0; k < mem_[var].size() && k < 4; ++k)
        v[k] = std::bit_cast<float>(mem_[var][k]);
      if (builtin_.count(var) && builtin_[var] == uint32_t(spv::BuiltIn::Position))
        position = v;
      else if (location_.count(var))
        outputs[location_[var]] = v;
    }
  }

private:
  using Op = spv::Op;
  using Words = std::vector<uint32_t>;
  struct Var {
    spv::StorageClass sc;
    Words init;
  };

  uint32_t op_at(size_t i) const { return w_[i] & 0xFFFF; }
  uint32_t len_at(size_t i) const { return w_[i] >> 16; }

  uint32_t size_of(uint32_t type) const {
    auto it = vec_n_.find(type);
    if (it != vec_n_.end()) return it->second;
    return 1;
  }

  void scan() {
    for (size_t i = 5; i < w_.size(); i += len_at(i)) {
      if (len_at(i) == 0) throw std::runtime_error("bad word count");
      const auto op = static_cast<Op>(op_at(i));
      const uint32_t* a = &w_[i + 1];
      switch (op) {
      case Op::OpEntryPoint: entry_ = a[1]; break;
      case Op::OpTypeVector: vec_n_[a[0]] = a[2]; break;
      case Op::OpDecorate:
        if (a[1] == uint32_t(spv::Decoration::Location)) location_[a[0]] = a[2];
        if (a[1] == uint32_t(spv::Decoration::BuiltIn)) builtin_[a[0]] = a[2];
        if (a[1] == uint32_t(spv::Decoration::ArrayStride)) stride_[a[0]] = a[2];
        break;
      case Op::OpMemberDecorate:
        if (a[2] == uint32_t(spv::Decoration::Offset)) offset_[{a[0], a[1]}] = a[3];
        break;
      case Op::OpTypeArray: elem_[a[0]] = a[1]; break;
      case Op::OpTypeStruct:
        for (uint32_t k = 1; k + 1 < len_at(i); ++k) member_[{a[0], k - 1}] = a[k];
        break;
      case Op::OpTypePointer: pointee_[a[0]] = a[2]; break;
      case Op::OpConstant:
      case Op::OpSpecConstant: val_[a[1]] = {a[2]}; break;
      case Op::OpConstantTrue:
      case Op::OpSpecConstantTrue: val_[a[1]] = {1}; break;
      case Op::OpConstantFalse:
      case Op::OpSpecConstantFalse: val_[a[1]] = {0}; break;
      case Op::OpConstantNull: val_[a[1]] = Words(size_of(a[0]), 0); break;
      case Op::OpConstantComposite: {
        Words v;
        for (uint32_t k = 3; k < len_at(i); ++k) v.push_back(val_[w_[i + k]][0]);
        val_[a[1]] = v;
        break;
      }
      case Op::OpVariable: {
        Var var{static_cast<spv::StorageClass>(a[2]), Words(size_of(pointee_[a[0]]), 0)};
        if (len_at(i) > 4) var.init = val_[a[3]];
        vars_[a[1]] = var;
        val_[a[1]] = {a[1], 0}; // pointer: variable, word offset
        break;
      }
      case Op::OpFunction: fn_start_[a[1]] = i + len_at(i); break;
      case Op::OpLabel: label_[a[0]] = i; break;
      default: break;
      }
    }
  }

  float fl(uint32_t id, size_t k) const { return std::bit_cast<float>(val_.at(id)[k]); }
  int32_t in(uint32_t id, size_t k) const { return static_cast<int32_t>(val_.at(id)[k]); }
  static uint32_t bits(float f) { return std::bit_cast<uint32_t>(f); }

  template <typename F> Words map2(uint32_t x, uint32_t y, F f) const {
    Words r;
    for (size_t k = 0; k < val_.at(x).size(); ++k) r.push_back(f(k));
    (void)y;
    return r;
  }

  void call(uint32_t fn) {
    size_t pc = fn_start_.at(fn);
    for (int guard = 0; guard < 1'000'000; ++guard) {
      const auto op = static_cast<Op>(op_at(pc));
      const uint32_t* a = &w_[pc + 1];
      const uint32_t n = len_at(pc);
      size_t next = pc + n;
      auto fbin = [&](auto f) {
        val_[a[1]] = map2(a[2], a[3], [&](size_t k) { return bits(f(fl(a[2], k), fl(a[3], k))); });
      };
      auto fcmp = [&](auto f) {
        val_[a[1]] =
            map2(a[2], a[3], [&](size_t k) { return uint32_t(f(fl(a[2], k), fl(a[3], k))); });
      };
      auto icmp = [&](auto f) {
        val_[a[1]] =
            map2(a[2], a[3], [&](size_t k) { return uint32_t(f(in(a[2], k), in(a[3], k))); });
      };
      switch (op) {
      case Op::OpLabel:
      case Op::OpSelectionMerge:
      case Op::OpLoopMerge: break;
      case Op::OpLoad: {
        const Words& p = val_.at(a[2]);
        const Words& m = mem_.at(p[0]);
        Words v(size_of(a[0]));
        for (size_t k = 0; k < v.size(); ++k) v[k] = p[1] + k < m.size() ? m[p[1] + k] : 0;
        val_[a[1]] = v;
        break;
      }
      case Op::OpStore: {
        const Words p = val_.at(a[0]);
        const Words& v = val_.at(a[1]);
        for (size_t k = 0; k < v.size(); ++k) mem_[p[0]][p[1] + k] = v[k];
        break;
      }
      case Op::OpAccessChain: {
        // Uniform block only: struct member, then array element.
        Words p = val_.at(a[2]);
        uint32_t type = pointee_.at(result_ptr_type(a[2]));
        const uint32_t member = val_.at(a[3])[0];
        p[1] += offset_.at({type, member}) / 4;
        type = member_.at({type, member});
        if (n > 5) p[1] += static_cast<uint32_t>(in(a[4], 0)) * stride_.at(type) / 4;
        val_[a[1]] = p;
        break;
      }
      case Op::OpCompositeConstruct: {
        Words v;
        for (uint32_t k = 2; k + 1 < n; ++k)
          for (uint32_t x : val_.at(a[k])) v.push_back(x);
        val_[a[1]] = v;
        break;
      }
      case Op::OpCompositeExtract: val_[a[1]] = {val_.at(a[2]).at(a[3])}; break;
      case Op::OpVectorShuffle: {
        Words both = val_.at(a[2]);
        for (uint32_t x : val_.at(a[3])) both.push_back(x);
        Words v;
        for (uint32_t k = 4; k + 1 < n; ++k) v.push_back(both.at(a[k]));
        val_[a[1]] = v;
        break;
      }
      case Op::OpFAdd: fbin([](float x, float y) { return x + y; }); break;
      case Op::OpFSub: fbin([](float x, float y) { return x - y; }); break;
      case Op::OpFMul: fbin([](float x, float y) { return x * y; }); break;
      case Op::OpFDiv: fbin([](float x, float y) { return x / y; }); break;
      case Op::OpFNegate:
        val_[a[1]] = map2(a[2], a[2], [&](size_t k) { return bits(-fl(a[2], k)); });
        break;
      case Op::OpFOrdEqual: fcmp([](float x, float y) { return x == y; }); break;
      case Op::OpFOrdLessThan: fcmp([](float x, float y) { return x < y; }); break;
      case Op::OpFOrdGreaterThan: fcmp([](float x, float y) { return x > y; }); break;
      case Op::OpFOrdGreaterThanEqual: fcmp([](float x, float y) { return x >= y; }); break;
      case Op::OpLogicalOr: icmp([](int32_t x, int32_t y) { return x || y; }); break;
      case Op::OpLogicalAnd: icmp([](int32_t x, int32_t y) { return x && y; }); break;
      case Op::OpLogicalNot:
        val_[a[1]] = map2(a[2], a[2], [&](size_t k) { return uint32_t(!in(a[2], k)); });
        break;
      case Op::OpIEqual: icmp([](int32_t x, int32_t y) { return x == y; }); break;
      case Op::OpINotEqual: icmp([](int32_t x, int32_t y) { return x != y; }); break;
      case Op::OpSLessThan: icmp([](int32_t x, int32_t y) { return x < y; }); break;
      case Op::OpSLessThanEqual: icmp([](int32_t x, int32_t y) { return x <= y; }); break;
      case Op::OpSGreaterThan: icmp([](int32_t x, int32_t y) { return x > y; }); break;
      case Op::OpSGreaterThanEqual: icmp([](int32_t x, int32_t y) { return x >= y; }); break;
      case Op::OpBitcast: val_[a[1]] = val_.at(a[2]); break;
      case Op::OpBitwiseAnd:
        icmp([](int32_t x, int32_t y) { return uint32_t(x) & uint32_t(y); });
        break;
      case Op::OpIAdd: icmp([](int32_t x, int32_t y) { return uint32_t(x) + uint32_t(y); }); break;
      case Op::OpISub: icmp([](int32_t x, int32_t y) { return uint32_t(x) - uint32_t(y); }); break;
      case Op::OpSelect: {
        const Words& c = val_.at(a[2]);
        val_[a[1]] = map2(a[3], a[3], [&](size_t k) {
          return c[c.size() == 1 ? 0 : k] ? val_.at(a[3])[k] : val_.at(a[4])[k];
        });
        break;
      }
      case Op::OpIsNan:
        val_[a[1]] = map2(a[2], a[2], [&](size_t k) { return uint32_t(std::isnan(fl(a[2], k))); });
        break;
      case Op::OpConvertFToS:
        val_[a[1]] = {static_cast<uint32_t>(static_cast<int32_t>(fl(a[2], 0)))};
        break;
      case Op::OpExtInst: {
        const uint32_t inst = a[3], x = a[4];
        val_[a[1]] = map2(x, x, [&](size_t k) {
          const float v = fl(x, k);
          switch (inst) {
          case GLSLstd450FAbs: return bits(std::fabs(v));
          case GLSLstd450Floor: return bits(std::floor(v));
          case GLSLstd450Sqrt: return bits(std::sqrt(v));
          case GLSLstd450Log2: return bits(std::log2(v));
          case GLSLstd450Exp2: return bits(std::exp2(v));
          case GLSLstd450Sin: return bits(std::sin(v));
          case GLSLstd450Cos: return bits(std::cos(v));
          default: throw std::runtime_error("ext inst " + std::to_string(inst));
          }
        });
        break;
      }
      case Op::OpImageSampleImplicitLod: {
        // A fake texture that returns its coordinate: (u, v, w or 0, 1 + bias).
        const Words& c = val_.at(a[3]);
        const float bias = n > 5 ? fl(a[5], 0) : 0.0f;
        val_[a[1]] = {c[0], c[1], c.size() > 2 ? c[2] : 0u, bits(1.0f + bias)};
        break;
      }
      case Op::OpFunctionCall:
        call(a[2]);
        if (killed) return;
        break;
      case Op::OpBranch: next = label_.at(a[0]); break;
      case Op::OpBranchConditional: next = label_.at(val_.at(a[0])[0] ? a[1] : a[2]); break;
      case Op::OpReturn: return;
      case Op::OpKill: killed = true; return;
      default: throw std::runtime_error("opcode " + std::to_string(op_at(pc)));
      }
      pc = next;
    }
    throw std::runtime_error("no termination");
  }

  uint32_t result_ptr_type(uint32_t var) const {
    for (size_t i = 5; i < w_.size(); i += len_at(i))
      if (static_cast<Op>(op_at(i)) == Op::OpVariable && w_[i + 2] == var) return w_[i + 1];
    throw std::runtime_error("no variable");
  }

  Words w_;
  uint32_t entry_ = 0;
  std::map<uint32_t, uint32_t> vec_n_, location_, builtin_, stride_, elem_, pointee_;
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> offset_, member_;
  std::map<uint32_t, Words> val_, mem_;
  std::map<uint32_t, Var> vars_;
  std::map<uint32_t, size_t> fn_start_, label_;
};

} // namespace tierlift::spirv_test
