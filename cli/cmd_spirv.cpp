// tierlift spirv FILE [--pair OTHER]: a listing as a SPIR-V module (checked by spirv-val
// in-process), optionally linked with its other stage so that what that stage never uses
// is left out (--explain lists it).
#include <fmt/format.h>

#include "commands.h"
#include "front_end.h"
#include "report.h"
#include "tierlift/codegen/codegen.h"

namespace tierlift::cli {

void register_spirv_command(CLI::App& app) {
  struct Opts {
    std::string file, pair, output;
    bool dis = false, opt = false, explain = false;
    FrontEndOptions fe;
  };
  auto opts = std::make_shared<Opts>();
  CLI::App* sub =
      app.add_subcommand("spirv", "Compile a listing to SPIR-V (validated by spirv-val)");
  sub->add_option("file", opts->file, "Listing ('-' reads standard input)")->required();
  sub->add_option("--pair", opts->pair,
                  "The other stage's listing: link both and leave out what the pair never uses");
  sub->add_option("-o,--output", opts->output,
                  "Write FILE's module as a SPIR-V binary ('-': standard output)");
  sub->add_flag("--dis", opts->dis, "Print the module as SPIR-V assembly text");
  sub->add_flag("--opt", opts->opt, "Run spirv-opt's performance passes");
  sub->add_flag("--explain", opts->explain, "List what linking with --pair left out");
  add_front_end_options(sub, opts->fe, false);
  set_action(sub, [opts] {
    Report report("spirv", opts->fe.json);
    if (!opts->output.empty()) {
      std::string why =
          check_output(opts->output, {opts->file, opts->pair}, opts->fe.json).message();
      if (why.empty() && opts->output == "-" && (opts->dis || opts->explain))
        why = "-o - writes the binary module to standard output; --dis and --explain print "
              "there too";
      if (!why.empty()) {
        report.error(opts->output == "-" ? "usage" : "io", why, opts->output);
        return report.finish(kExitUsage);
      }
    }
    ir::Result<LoadedListing> main = load_listing(opts->file, opts->fe);
    std::optional<ir::Result<LoadedListing>> other;
    if (!opts->pair.empty()) other.emplace(load_listing(opts->pair, opts->fe));
    for (const ir::Result<LoadedListing>* l : {&main, other ? &*other : nullptr}) {
      if (!l) continue;
      if (!*l) {
        report.error("io", l->message());
        return report.finish(kExitUsage);
      }
      if (ir::Status out = refuse_included(opts->output, **l); !out) {
        report.error("io", out.message(), opts->output);
        return report.finish(kExitUsage);
      }
      report.diagnostics((*l)->diags, (*l)->sources);
      if (!(*l)->program) return report.finish(kExitInvalid); // never compile an invalid listing
    }
    codegen::CodegenOptions copts;
    copts.optimize = opts->opt;
    ir::DiagnosticSink diags;
    std::optional<codegen::ShaderModule> module;
    std::vector<codegen::PrunedItem> pruned;
    if (other) {
      const ir::Program& a = *main->program;
      const ir::Program& b = *(*other)->program;
      if (a.stage() == b.stage()) {
        report.error("usage", "--pair needs one vertex and one pixel listing");
        return report.finish(kExitUsage);
      }
      const ir::Program& vs = a.stage() == ir::ShaderStage::Vertex ? a : b;
      const ir::Program& ps = a.stage() == ir::ShaderStage::Vertex ? b : a;
      if (auto pair = codegen::compile_pair(vs, ps, copts, diags)) {
        module = a.stage() == ir::ShaderStage::Vertex ? pair->vs : pair->ps;
        pruned = std::move(pair->pruned);
      }
    } else {
      module = codegen::compile(*main->program, copts, diags);
    }
    report.diagnostics(diags, main->sources);
    if (!module) {
      report.error("codegen", "SPIR-V generation failed");
      return report.finish(kExitInvalid);
    }
    report.result()["words"] = module->words.size();
    if (opts->explain) {
      std::string text = codegen::explain(pruned);
      report.output("explain", text.empty() ? std::string("nothing was left out\n") : text);
    }
    if (opts->dis) {
      ir::Result<std::string> text = codegen::disassemble(module->words);
      if (!text) {
        report.error("codegen", text.message());
        return report.finish(kExitInvalid);
      }
      report.output("disassembly", *text);
    }
    if (!opts->output.empty()) {
      std::string bytes(reinterpret_cast<const char*>(module->words.data()),
                        module->words.size() * sizeof(uint32_t));
      if (std::string error = write_output(opts->output, bytes); !error.empty()) {
        report.error("io", error, opts->output);
        return report.finish(kExitUsage);
      }
      report.result()["written"] = opts->output;
    }
    if (!opts->dis && !opts->explain && opts->output.empty() && !report.json())
      fmt::print("{}: ok ({} words, spirv-val passed)\n", opts->file, module->words.size());
    return report.finish(kExitOk);
  });
}

} // namespace tierlift::cli
