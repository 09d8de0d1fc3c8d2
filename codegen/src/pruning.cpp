// Link-time pruning of a VS/PS pair, driven by the IR liveness passes (ir/liveness.h): the
// pixel shader's live instructions decide which interpolants it reads; the vertex shader
// declares exactly those outputs (plus position and point size), drops instructions whose
// results nobody reads, and with them the inputs and constants only they read. Everything
// left out is reported here as a PrunedItem.
#include <map>
#include <set>

#include "tierlift/codegen/codegen.h"
#include "tierlift/codegen/emitter.h"
#include "tierlift/ir/liveness.h"
#include "tierlift/ir/passes.h"
#include "tierlift/ir/result_diagnostics.h"
#include "tierlift/ir/sm3_interface.h"

namespace tierlift::codegen {

using ir::RegFile;
using Reg = ir::RegKey;

namespace {

std::string describe(const ir::Instruction& ins) {
  std::string s(ir::op_info(ins.op).mnemonic);
  if (ins.dst) { // appended piece by piece: " " + temporary trips GCC 12's false -Wrestrict
    s += ' ';
    s += ir::register_name(ins.dst->file, ins.dst->index);
    s += ir::mask_text(ins.dst->mask);
  }
  return s;
}

void note_unread(const ir::Program& prog, const std::vector<bool>& dead, ir::ShaderStage stage,
                 std::vector<PrunedItem>& out) {
  // v[aL + n] may read any declared input: none is reported unread.
  const bool inputs_relative = ir::reads_inputs_relatively(prog);
  std::set<Reg> read_live, read_dead;
  bool relative = false;
  for (size_t i = 0; i < prog.code.size(); ++i) {
    const ir::RegisterReads r = ir::registers_read(prog.code[i], prog.profile);
    for (const Reg& reg : r.regs) (dead[i] ? read_dead : read_live).insert(reg);
    if (!dead[i] && r.const_relative) relative = true;
  }
  for (size_t i = 0; i < prog.code.size(); ++i)
    if (dead[i])
      out.push_back({PrunedItem::Kind::DeadInstruction, stage, describe(prog.code[i]),
                     "its result is never used", prog.code[i].loc});
  for (const ir::Declaration& d : prog.decls) {
    const RegFile f = d.reg.file;
    if ((f != RegFile::Input && f != RegFile::Texture) || inputs_relative) continue;
    Reg key{f, d.reg.index};
    bool used =
        read_live.count(key) > 0 || read_live.count({f, ir::kTexCoordKey + d.reg.index}) > 0;
    if (!used)
      out.push_back({stage == ir::ShaderStage::Vertex ? PrunedItem::Kind::VertexInput
                                                      : PrunedItem::Kind::PixelInput,
                     stage, ir::register_name(f, d.reg.index), "never read", d.loc});
  }
  if (relative) return;
  for (const Reg& r : read_dead)
    if (r.first == RegFile::Const && !read_live.count(r))
      out.push_back({PrunedItem::Kind::Constant,
                     stage,
                     ir::register_name(r.first, r.second),
                     "read only by removed instructions",
                     {}});
}

} // namespace

namespace {
// Whether the liveness passes may drop instructions of `p`: not in 2.x and 3.0, whose
// breaks, predicated writes and setp they do not model; those programs are emitted whole.
bool prunable(const ir::Program& p) {
  return !ir::has_predication(p.profile);
}

// compile_pair after the checks, on programs linked by semantic.
// `*_links`: ir::relative_input_links of each program before linking; `vs_out_links`:
// ir::relative_output_links of the vertex program.
std::optional<CompiledPair>
compile_linked_pair(const ir::Program& vs, const ir::Program& ps, ir::RelativeLinks vs_links,
                    ir::RelativeLinks ps_links, ir::RelativeLinks vs_out_links,
                    const CodegenOptions& options, ir::DiagnosticSink& diags) {
  CompiledPair pair;
  EmitPlan ps_plan;
  ps_plan.skip = prunable(ps) ? ir::dead_instructions(ps, ir::pixel_live_out(ps))
                              : std::vector<bool>(ps.code.size(), false);
  std::set<Reg> wanted = ir::live_inputs(ps, ps_plan.skip);
  // v[aL + n] may read any input the pixel program declares.
  if (ir::reads_inputs_relatively(ps))
    for (const auto& link : ps_links)
      if (link)
        wanted.insert(
            {link->first == RegFile::Input ? RegFile::AttrOut : RegFile::TexCrdOut, link->second});
  ps_plan.relative_inputs = std::move(ps_links);

  EmitPlan vs_plan;
  vs_plan.relative_inputs = std::move(vs_links);
  vs_plan.saturate_color_outputs = ir::saturates_vertex_colors(vs.profile, ps.profile);
  vs_plan.vs_outputs = wanted;
  std::set<Reg> written;
  for (const ir::Instruction& ins : vs.code)
    if (ins.dst && !ins.dst->rel) written.insert({ins.dst->file, ins.dst->index});
  // o[aL + n] may write any output the vertex program declares.
  if (ir::writes_outputs_relatively(vs))
    for (const auto& link : vs_out_links)
      if (link) written.insert(*link);
  vs_plan.relative_outputs = std::move(vs_out_links);
  if (written.count({RegFile::RastOut, ir::kRastPts}))
    vs_plan.vs_outputs->insert({RegFile::RastOut, ir::kRastPts});
  for (const Reg& r : ir::dead_outputs(vs, wanted)) {
    const char* reads = r.first == RegFile::AttrOut ? "v" : "t";
    pair.pruned.push_back(
        {PrunedItem::Kind::VertexOutput,
         ir::ShaderStage::Vertex,
         ir::register_name(r.first, r.second),
         r.first == RegFile::RastOut
             ? std::string("fog is fixed-function state, no pixel shader reads it")
             : "the pixel shader never reads " + std::string(reads) + std::to_string(r.second),
         {}});
  }
  for (const Reg& r : wanted)
    if (!written.count(r))
      diags.warning(ps.version_loc, "link",
                    "the pixel shader reads " +
                        std::string(r.first == RegFile::AttrOut ? "v" : "t") +
                        std::to_string(r.second) + ", which the vertex shader never writes (" +
                        ir::register_name(r.first, r.second) + " reads (0,0,0,0))");
  std::map<Reg, uint8_t> vs_live;
  for (const Reg& r : *vs_plan.vs_outputs) vs_live[r] = 0xF;
  vs_live[{RegFile::RastOut, ir::kRastPos}] = 0xF;
  vs_plan.skip =
      prunable(vs) ? ir::dead_instructions(vs, vs_live) : std::vector<bool>(vs.code.size(), false);
  note_unread(vs, vs_plan.skip, ir::ShaderStage::Vertex, pair.pruned);
  note_unread(ps, ps_plan.skip, ir::ShaderStage::Pixel, pair.pruned);

  Emitter ve(vs, options, vs_plan, diags);
  auto vm = ve.run();
  Emitter pe(ps, options, ps_plan, diags);
  auto pm = pe.run();
  if (!vm || !pm) return std::nullopt;
  pair.vs = std::move(*vm);
  pair.ps = std::move(*pm);
  return pair;
}

} // namespace

std::optional<CompiledPair> compile_pair(const ir::Program& vs_listing,
                                         const ir::Program& ps_listing,
                                         const CodegenOptions& options, ir::DiagnosticSink& diags) {
  if (vs_listing.stage() != ir::ShaderStage::Vertex ||
      ps_listing.stage() != ir::ShaderStage::Pixel) {
    diags.error(vs_listing.version_loc, "codegen",
                "compile_pair needs a vertex and a pixel shader");
    return std::nullopt;
  }
  for (const ir::Program* p : {&vs_listing, &ps_listing})
    for (ir::Status s : {ir::validate_ir(*p), ir::check_executable(*p, "SPIR-V")})
      if (!s) { // as compile() does, before any analysis
        ir::add_all(diags, s.diagnostics());
        return std::nullopt;
      }
  // Shader model 3 links by semantic: from here on both stages speak the 2.0 interface
  // (a vs_2_0's oFog moved to where a ps_3_0 reads fog0 first).
  const ir::Program vs_linked = ir::link_by_semantic(ir::feed_fog(vs_listing, ps_listing));
  const ir::Program ps_linked = ir::link_by_semantic(ps_listing);
  return compile_linked_pair(vs_linked, ps_linked, ir::relative_input_links(vs_listing),
                             ir::relative_input_links(ps_listing),
                             ir::relative_output_links(vs_listing), options, diags);
}

} // namespace tierlift::codegen
