// The .tss reader (stage_states.h, docs/stage-states.md): one statement a line, words
// separated by blanks, `#` or `//` starting a comment. Names are case-insensitive and may
// carry their Direct3D prefix (D3DTSS_COLOROP, D3DTOP_MODULATE, D3DTA_TEXTURE).
#include <algorithm>
#include <cctype>
#include <charconv>

#include <fmt/format.h>

#include "tierlift/effects/glow/stage_states.h"

namespace tierlift::effects::tss {
namespace {

struct Word {
  std::string text; // lower-cased
  ir::SourceLoc loc;
};

std::string lower(std::string_view s) {
  std::string r(s);
  for (char& ch : r) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  return r;
}

std::string strip_prefix(std::string s, std::string_view prefix) {
  if (s.starts_with(prefix)) s.erase(0, prefix.size());
  return s;
}

// The words of one line, up to a comment; "stage 0:" gives "stage", "0", ":".
std::vector<Word> split(std::string_view line, uint32_t file, uint32_t line_no) {
  std::vector<Word> out;
  size_t i = 0;
  while (i < line.size()) {
    const char ch = line[i];
    if (ch == '#' || (ch == '/' && i + 1 < line.size() && line[i + 1] == '/')) break;
    if (std::isspace(static_cast<unsigned char>(ch))) {
      ++i;
      continue;
    }
    size_t j = i;
    if (ch == ':' || ch == ',') {
      j = i + 1;
    } else {
      while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j])) &&
             line[j] != ':' && line[j] != ',' && line[j] != '#')
        ++j;
    }
    ir::SourceLoc loc;
    loc.file = file;
    loc.line = line_no;
    loc.col = uint32_t(i + 1);
    loc.length = uint32_t(j - i);
    out.push_back({lower(line.substr(i, j - i)), loc});
    i = j;
  }
  return out;
}

struct OpName {
  std::string_view name;
  Op op;
  size_t args;
};
constexpr OpName kOps[] = {
    {"disable", Op::Disable, 0},
    {"selectarg1", Op::SelectArg1, 1},
    {"selectarg2", Op::SelectArg2, 2},
    {"modulate", Op::Modulate, 2},
    {"modulate2x", Op::Modulate2x, 2},
    {"modulate4x", Op::Modulate4x, 2},
    {"add", Op::Add, 2},
    {"addsigned", Op::AddSigned, 2},
    {"subtract", Op::Subtract, 2},
    {"modulatealpha_addcolor", Op::ModulateAlphaAddColor, 2},
};
struct ArgName {
  std::string_view name;
  Arg arg;
};
constexpr ArgName kArgs[] = {{"current", Arg::Current},
                             {"diffuse", Arg::Diffuse},
                             {"specular", Arg::Specular},
                             {"texture", Arg::Texture},
                             {"tfactor", Arg::TFactor}};

std::string op_list() {
  std::string s;
  for (const OpName& o : kOps) s += (s.empty() ? "" : ", ") + std::string(o.name);
  return s;
}

class Reader {
public:
  Reader(uint32_t file, const ir::SourceManager& sm, ir::DiagnosticSink& d, uint32_t max)
      : file_(file), sm_(sm), diags_(d), max_stages_(max) {}

  std::optional<StageStates> run() {
    const std::string& text = sm_.files[file_].text;
    size_t start = 0;
    uint32_t line_no = 0;
    const size_t errors_before = diags_.error_count();
    while (start <= text.size()) {
      size_t end = text.find('\n', start);
      if (end == std::string::npos) end = text.size();
      std::string_view line(text.data() + start, end - start);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      ++line_no;
      statement(split(line, file_, line_no));
      if (end == text.size()) break;
      start = end + 1;
    }
    check_cascade();
    if (diags_.error_count() > errors_before) return std::nullopt;
    return states_;
  }

private:
  void error(const ir::SourceLoc& loc, std::string rule, std::string message) {
    diags_.error(loc, std::move(rule), std::move(message));
  }

  ir::SourceLoc end_of(const std::vector<Word>& w) const {
    ir::SourceLoc loc = w.back().loc;
    loc.col += loc.length;
    loc.length = 1;
    return loc;
  }

  void statement(const std::vector<Word>& w) {
    if (w.empty()) return;
    if (strip_prefix(w[0].text, "d3drs_") == "tfactor" ||
        strip_prefix(w[0].text, "d3drs_") == "texturefactor")
      return tfactor(w);
    if (w[0].text != "stage")
      return error(w[0].loc, "tss-statement",
                   fmt::format("'{}' is not a statement; expected 'stage N: STATE OPERATION "
                               "ARGUMENTS' or 'tfactor 0xAARRGGBB'",
                               w[0].text));
    if (w.size() < 2) return error(end_of(w), "tss-syntax", "expected a stage number");
    uint32_t n = 0;
    const std::string& num = w[1].text;
    auto [p, ec] = std::from_chars(num.data(), num.data() + num.size(), n);
    const bool digits = ec != std::errc::invalid_argument && p == num.data() + num.size();
    if (!digits)
      return error(
          w[1].loc, "tss-syntax",
          fmt::format("'{}' is not a stage number; expected 0..{}", num, kD3DMaxStages - 1));
    if (ec == std::errc::result_out_of_range || n >= kD3DMaxStages)
      return error(w[1].loc, "tss-range",
                   fmt::format("stage {} is out of range: Direct3D numbers texture stages "
                               "0..{}",
                               num, kD3DMaxStages - 1));
    if (n >= max_stages_)
      return error(w[1].loc, "tss-stage-count",
                   fmt::format("stage {}: this tier blends {} textures in a pass (stages 0..{}); "
                               "a third texture needs a second pass",
                               n, max_stages_, max_stages_ - 1));
    size_t i = 2;
    if (i < w.size() && w[i].text == ":") ++i;
    if (i >= w.size())
      return error(end_of(w), "tss-syntax", "expected a state (colorop or alphaop)");
    if (states_.stages.size() <= n) states_.stages.resize(n + 1);
    Stage& stage = states_.stages[n];
    if (!stage.first.valid()) stage.first = w[0].loc;
    const std::string state = strip_prefix(w[i].text, "d3dtss_");
    std::optional<Operation>* slot = nullptr;
    if (state == "colorop")
      slot = &stage.color;
    else if (state == "alphaop")
      slot = &stage.alpha;
    else
      return error(w[i].loc, "tss-unknown-state",
                   fmt::format("unknown texture-stage state '{}'; tierlift reads colorop and "
                               "alphaop (their arguments follow the operation)",
                               w[i].text));
    if (*slot)
      return error(
          w[i].loc, "tss-duplicate",
          fmt::format("stage {}: {} is set twice (first at line {})", n, state, (*slot)->loc.line));
    if (++i >= w.size()) return error(end_of(w), "tss-syntax", "expected an operation");
    const std::string opname = strip_prefix(w[i].text, "d3dtop_");
    const auto op = std::find_if(std::begin(kOps), std::end(kOps),
                                 [&](const OpName& o) { return o.name == opname; });
    if (op == std::end(kOps))
      return error(w[i].loc, "tss-unknown-op",
                   fmt::format("unknown operation '{}'; expected one of {}", w[i].text, op_list()));
    if (op->op == Op::ModulateAlphaAddColor && state == "alphaop")
      return error(w[i].loc, "tss-color-only",
                   "modulatealpha_addcolor is a colour operation; it has no alpha form");
    Operation o;
    o.op = op->op;
    o.loc = w[i].loc;
    for (++i; i < w.size(); ++i) {
      if (w[i].text == ",") continue;
      const std::string a = strip_prefix(w[i].text, "d3dta_");
      const auto arg = std::find_if(std::begin(kArgs), std::end(kArgs),
                                    [&](const ArgName& x) { return x.name == a; });
      if (arg == std::end(kArgs))
        return error(w[i].loc, "tss-unknown-arg",
                     fmt::format("unknown argument '{}'; expected current, diffuse, specular, "
                                 "texture or tfactor",
                                 w[i].text));
      if (o.args.size() == op->args)
        return error(
            w[i].loc, "tss-arg-count",
            fmt::format("{} takes {} argument{}", op->name, op->args, op->args == 1 ? "" : "s"));
      o.args.push_back(arg->arg);
    }
    if (o.args.size() < op->args)
      return error(end_of(w), "tss-arg-count",
                   fmt::format("{} takes {} argument{}, {} given", op->name, op->args,
                               op->args == 1 ? "" : "s", o.args.size()));
    *slot = std::move(o);
  }

  void tfactor(const std::vector<Word>& w) {
    if (w.size() != 2)
      return error(w.size() < 2 ? end_of(w) : w[2].loc, "tss-syntax",
                   "expected 'tfactor 0xAARRGGBB'");
    std::string v = w[1].text;
    if (!v.starts_with("0x"))
      return error(w[1].loc, "tss-syntax",
                   fmt::format("'{}': the texture factor is a D3DCOLOR written 0xAARRGGBB", v));
    uint64_t x = 0;
    auto [p, ec] = std::from_chars(v.data() + 2, v.data() + v.size(), x, 16);
    if (ec == std::errc::invalid_argument || p != v.data() + v.size() || v.size() == 2)
      return error(w[1].loc, "tss-syntax", fmt::format("'{}' is not a hexadecimal number", v));
    if (ec == std::errc::result_out_of_range || x > 0xFFFFFFFFull)
      return error(w[1].loc, "tss-range",
                   fmt::format("{} is out of range: a D3DCOLOR has 32 bits (0xAARRGGBB)", v));
    if (states_.tfactor_loc.valid())
      return error(
          w[0].loc, "tss-duplicate",
          fmt::format("tfactor is set twice (first at line {})", states_.tfactor_loc.line));
    states_.tfactor = uint32_t(x);
    states_.tfactor_loc = w[0].loc;
  }

  // Direct3D stops at the first stage whose colour operation is disabled; a stage named after
  // it would never run, and a stage with no colorop at all is disabled (stage 0 aside).
  void check_cascade() {
    bool ended = false;
    uint32_t end_stage = 0;
    for (uint32_t n = 0; n < states_.stages.size(); ++n) {
      const Stage& s = states_.stages[n];
      const bool named = s.first.valid();
      if (ended && named) {
        error(s.first, "tss-cascade",
              fmt::format("stage {} never runs: stage {} ends the cascade (its colorop is "
                          "disable or not set)",
                          n, end_stage));
        return;
      }
      const bool disabled = !named ? n > 0 : (s.color ? s.color->op == Op::Disable : n > 0);
      if (named && !s.color && n > 0) {
        error(s.first, "tss-missing-colorop",
              fmt::format("stage {} has no colorop (Direct3D disables stages after 0 by "
                          "default); set one, or 'colorop disable'",
                          n));
        return;
      }
      if (disabled && !ended) ended = true, end_stage = n;
    }
  }

  uint32_t file_;
  const ir::SourceManager& sm_;
  ir::DiagnosticSink& diags_;
  uint32_t max_stages_;
  StageStates states_;
};

} // namespace

std::optional<StageStates> parse_stage_states(uint32_t file, const ir::SourceManager& sources,
                                              ir::DiagnosticSink& diags, uint32_t max_stages) {
  if (file >= sources.files.size()) return std::nullopt;
  return Reader(file, sources, diags, max_stages).run();
}

float d3dcolor_channel(uint8_t byte) {
  return static_cast<float>(byte / 255.0);
}

} // namespace tierlift::effects::tss
