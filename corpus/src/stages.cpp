// The stages before the draw: parse, validate, token round trip, SPIR-V. Each records its
// verdict and its time; a stage whose input an earlier stage could not give is skipped.
#include "tierlift/corpus/stages.h"

#include <chrono>
#include <regex>

#include <fmt/format.h>

#include "diff_run.h"
#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/load.h"
#include "tierlift/codegen/codegen.h"
#include "tierlift/io/bounded_read.h"
#include "tierlift/ir/passes.h"
#include "tierlift/ir/profile.h"
#include "tierlift/ir/result_diagnostics.h"
#include "version_line.h"

namespace tierlift::corpus {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// The first lines of rendered diagnostics: enough to say why, short enough for a CSV cell.
std::string first_lines(const std::string& text, size_t lines = 3) {
  size_t pos = 0;
  for (size_t i = 0; i < lines && pos != std::string::npos; ++i) {
    pos = text.find('\n', pos);
    if (pos != std::string::npos) ++pos;
  }
  std::string out = text.substr(0, pos);
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out.size() > 600 ? out.substr(0, 600) + "…" : out;
}

// Shader model 4 and newer (Direct3D 10's profiles) are no Direct3D 9 listings: the front end
// refuses them and the case is "unsupported", not a failure. Told from the version line or
// token. (Shader models 2.x and 3.0 parse; their SPIR-V stage says "unsupported".)
bool newer_than_front_end(std::string_view bytes, assembly::ListingForm form) {
  if (form == assembly::ListingForm::TokenStream || form == assembly::ListingForm::Binary) {
    if (bytes.size() < 4) return false;
    const unsigned major = static_cast<unsigned char>(bytes[1]);
    const unsigned kind = static_cast<unsigned char>(bytes[2]) |
                          (static_cast<unsigned>(static_cast<unsigned char>(bytes[3])) << 8);
    return (kind == 0xFFFE || kind == 0xFFFF) && major >= 4;
  }
  if (form == assembly::ListingForm::TokenArray) {
    static const std::regex token(R"(0x[fF]{3}[eEfF]0[4-9]0)");
    return std::regex_search(bytes.begin(), bytes.end(), token);
  }
  const std::optional<char> major = version_line_major(bytes);
  return major && *major >= '4';
}

struct Front {
  ir::SourceManager sources;
  std::optional<assembly::Loaded> loaded;
};

// How a case is read: as `tierlift check` reads it (Windows' leniency applied), not validated
// (the validate stage does that, assembly::validate_loaded, with the same options).
assembly::LoadOptions front_end_options() {
  assembly::LoadOptions o;
  o.skip_validation = true;
  return o;
}

Front load(const std::string& path, const std::string& bytes) {
  Front f;
  uint32_t file = f.sources.add(path, bytes);
  f.loaded.emplace(assembly::load_listing(file, f.sources, front_end_options()));
  return f;
}

std::string rendered(const ir::Result<ir::Program>& r, const ir::SourceManager& sm) {
  return first_lines(ir::render_text(r.diagnostics(), sm));
}

StageResult round_trip(const Front& parsed) {
  StageResult s{std::string(kStageRoundTrip), Verdict::Pass, {}, 0};
  const ir::Program& program = *parsed.loaded->program;
  ir::DiagnosticSink diags;
  std::optional<std::vector<uint32_t>> tokens = assembly::assemble(program, diags);
  if (!tokens) {
    s.verdict = Verdict::Fail;
    s.message = "assemble: " + first_lines(ir::render_text(diags, parsed.sources));
    return s;
  }
  if (!parsed.loaded->tokens.empty()) { // bytecode in: assemble ∘ disassemble = identity,
    // comment blocks (CTAB and the like) included
    const std::vector<uint32_t>& original = parsed.loaded->tokens;
    for (size_t i = 0; i < std::max(original.size(), tokens->size()); ++i) {
      if (i < original.size() && i < tokens->size() && original[i] == (*tokens)[i]) continue;
      s.verdict = Verdict::Fail;
      s.message = fmt::format(
          "token {} differs after disassemble and assemble: read {}, written {}", i,
          i < original.size() ? fmt::format("0x{:08x}", original[i]) : std::string("(end)"),
          i < tokens->size() ? fmt::format("0x{:08x}", (*tokens)[i]) : std::string("(end)"));
      return s;
    }
    return s;
  }
  // Text in: disassemble ∘ assemble gives the same program.
  std::optional<ir::Program> back = assembly::disassemble(*tokens, diags);
  if (!back) {
    s.verdict = Verdict::Fail;
    s.message = "disassemble: " + first_lines(ir::render_text(diags, parsed.sources));
  } else if (!ir::same_ir(program, *back)) {
    s.verdict = Verdict::Fail;
    s.message =
        "assemble then disassemble changed the program: " + ir::ir_difference(program, *back);
  }
  return s;
}

StageResult spirv(const ir::Program& program, const ir::SourceManager& sm) {
  StageResult s{std::string(kStageSpirv), Verdict::Pass, {}, 0};
  // What neither the code generator nor the interpreter runs yet (in shader models 2.x and
  // 3.0: gradients, texldl, semantics without a 2.0 register; ir::check_executable) is
  // "unsupported", not a failure. Every other program goes on to the differential run.
  if (ir::Status runnable = ir::check_executable(program, "SPIR-V"); !runnable) {
    s.verdict = Verdict::Unsupported;
    s.message = runnable.message();
    return s;
  }
  ir::DiagnosticSink diags;
  if (!codegen::compile(program, codegen::CodegenOptions{}, diags)) {
    s.verdict = Verdict::Fail;
    s.message = first_lines(ir::render_text(diags, sm));
    if (s.message.empty()) s.message = "SPIR-V generation failed";
  }
  return s;
}

// Runs `body` as stage `name` when `ready`, else records it skipped.
template <class F>
void stage(CaseResult& r, std::string_view name, bool ready, const char* why_not, F&& body) {
  if (!ready) {
    r.stages.push_back({std::string(name), Verdict::Skip, why_not, 0});
    return;
  }
  const auto t0 = Clock::now();
  StageResult s = body();
  s.ms = ms_since(t0);
  r.stages.push_back(std::move(s));
}

Verdict overall(const CaseResult& r) {
  Verdict v = Verdict::Pass;
  for (const StageResult& s : r.stages) {
    if (is_failure(s.verdict)) return s.verdict;
    if (s.verdict == Verdict::Unsupported) v = Verdict::Unsupported;
  }
  return v;
}

} // namespace

CaseResult run_listing(const std::string& id, const std::string& display_path, std::string bytes,
                       const StageOptions& options) {
  const auto t0 = Clock::now();
  CaseResult r;
  r.id = id;
  if (bytes.starts_with("\xEF\xBB\xBF")) bytes.erase(0, 3); // a UTF-8 byte-order mark
  const assembly::ListingForm form = assembly::detect_listing_form(bytes);
  r.form = std::string(assembly::listing_form_name(form));

  const auto t_parse = Clock::now();
  Front parsed = load(display_path, bytes);
  StageResult parse{std::string(kStageParse), Verdict::Pass, {}, 0};
  if (!parsed.loaded->program) {
    parse.verdict = newer_than_front_end(bytes, form) ? Verdict::Unsupported : Verdict::Fail;
    parse.message = rendered(parsed.loaded->program, parsed.sources);
  } else {
    r.profile = std::string(ir::profile_name(parsed.loaded->program->profile));
  }
  parse.ms = ms_since(t_parse);
  const bool parsed_ok = parse.verdict == Verdict::Pass;
  r.stages.push_back(std::move(parse));

  // The program the parse stage read, validated as load_listing would: the listing is read
  // once.
  const ir::Program* valid = nullptr;
  stage(r, kStageValidate, parsed_ok, "not parsed", [&] {
    const ir::Program& program = *parsed.loaded->program;
    ir::DiagnosticSink diags;
    StageResult s{std::string(kStageValidate), Verdict::Pass, {}, 0};
    if (assembly::validate_loaded(program, front_end_options(), diags)) {
      valid = &program;
    } else {
      s.verdict = Verdict::Fail;
      s.message = first_lines(ir::render_text(diags, parsed.sources));
    }
    return s;
  });
  const bool run_more = !options.check_only;
  const char* later = options.check_only ? "check only" : "not valid";
  stage(r, kStageRoundTrip, parsed_ok && run_more, options.check_only ? later : "not parsed",
        [&] { return round_trip(parsed); });
  stage(r, kStageSpirv, valid && run_more, later, [&] { return spirv(*valid, parsed.sources); });
  const bool spirv_ok = r.stages.back().verdict == Verdict::Pass;
  stage(r, kStageDiff, spirv_ok && run_more && options.device,
        !options.device && run_more ? "no Vulkan device" : "no SPIR-V",
        [&] { return differential_run(*valid, id, options, r.difference); });
  r.verdict = overall(r);
  r.ms = ms_since(t0);
  return r;
}

CaseResult run_case(const Case& c, const StageOptions& options) {
  if (c.generated || c.path.empty()) return run_listing(c.id, c.id, c.text, options);
  ir::Result<std::string> bytes = io::read_bounded(c.path, io::kListingCap);
  if (!bytes) {
    CaseResult r;
    r.id = c.id;
    r.verdict = Verdict::Fail;
    r.stages.push_back({std::string(kStageParse), Verdict::Fail, bytes.message(), 0});
    return r;
  }
  return run_listing(c.id, c.path, std::move(*bytes), options);
}

} // namespace tierlift::corpus
