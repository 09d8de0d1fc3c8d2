// The D3DX-style preprocessor: directives, conditional blocks and #include, line by line.
// Macro expansion lives in macro_expander.cpp, #if arithmetic in pp_expr.cpp.
#include "tierlift/assembly/preprocessor.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "macros.h"
#include "pp_expr.h"

namespace tierlift::assembly {
namespace {

namespace fs = std::filesystem;
using detail::Macro;

constexpr int kMaxIncludeDepth = 32;
constexpr uintmax_t kMaxIncludeBytes = 16u << 20; // no shader header is anywhere near this
// Past this many errors the rest of the input is not worth reading.
constexpr size_t kMaxErrors = 100;

bool is_punct(const Token& t, std::string_view p) {
  return t.kind == TokKind::Punct && t.text == p;
}

struct Cond {
  bool parent_active; // the enclosing block is being read
  bool taken;         // some branch of this #if chain was already active
  bool active;        // the current branch is being read
  bool seen_else;
  ir::SourceLoc loc; // of the #if, for "unterminated #if"
};

class Preprocessor {
public:
  Preprocessor(ir::SourceManager& sm, ir::DiagnosticSink& diags, const ParseOptions& options,
               TokenStream& out)
      : sm_(sm), diags_(diags), options_(options), out_(out), first_error_(diags.error_count()),
        macros_(out.storage) {}

  void run(uint32_t file) {
    for (const auto& [name, value] : options_.defines) define_from_option(file, name, value);
    // The main file is part of the cycle check, so "a includes a" is caught at once.
    std::error_code ec;
    fs::path main_path(sm_.files[file].name);
    if (fs::is_regular_file(main_path, ec))
      include_stack_.push_back(fs::weakly_canonical(main_path, ec));
    process_file(file, 0);
    ir::SourceLoc end{file, 1, 1, 0};
    if (!out_.tokens.empty()) end = out_.tokens.back().loc;
    out_.tokens.push_back({TokKind::End, true, {}, end});
  }

private:
  std::string_view keep(std::string text) {
    out_.storage.push_back(std::make_unique<std::string>(std::move(text)));
    return *out_.storage.back();
  }
  bool too_many_errors() const { return diags_.error_count() - first_error_ >= kMaxErrors; }

  void define_from_option(uint32_t file, const std::string& name, const std::string& value) {
    std::vector<Token> name_toks, body;
    ir::DiagnosticSink scratch;
    lex_text(file, keep(name), scratch, name_toks);
    lex_text(file, keep(value.empty() ? std::string("1") : value), scratch, body);
    std::erase_if(body, [](const Token& t) { return t.kind == TokKind::Newline; });
    if (scratch.has_errors() || name_toks.size() != 2 || name_toks[0].kind != TokKind::Ident) {
      diags_.error({}, "preprocessor", fmt::format("bad -D definition '{}'", name));
      return;
    }
    Macro m;
    m.body = std::move(body);
    macros_.define(std::string(name_toks[0].text), std::move(m));
  }

  void process_file(uint32_t file, int depth) {
    std::string_view text = keep(sm_.files[file].text);
    LineLexer lexer(file, text, diags_);
    std::vector<Token> line;
    std::vector<Cond> conds;
    while (!too_many_errors()) {
      line.clear();
      if (!lexer.next_line(line)) break;
      if (line.size() == 1) continue; // only the Newline
      bool active = conds.empty() || conds.back().active;
      std::span<const Token> body(line.data(), line.size() - 1);
      if (is_punct(body[0], "#")) {
        directive(body, file, depth, conds);
        if (out_.binary) return; // an #include'd file was binary
      } else if (active) {
        macros_.expand(body, out_.tokens, diags_);
        out_.tokens.push_back(line.back());
      }
    }
    if (lexer.status() == LexStatus::Binary) {
      out_.binary = true;
      return;
    }
    for (const Cond& c : conds)
      diags_.error(c.loc, "preprocessor", "unterminated conditional directive (missing #endif)");
  }

  void directive(std::span<const Token> line, uint32_t file, int depth, std::vector<Cond>& conds) {
    if (line.size() == 1) return; // the null directive "#"
    const Token& name_tok = line[1];
    std::string_view name = name_tok.text;
    std::span<const Token> rest = line.subspan(2);
    bool active = conds.empty() || conds.back().active;
    ir::SourceLoc loc = line[0].loc;
    loc.length = static_cast<uint32_t>(name_tok.loc.col + name_tok.loc.length - loc.col);

    if (name == "if" || name == "ifdef" || name == "ifndef") {
      bool value = false;
      if (active) value = name == "if" ? eval_condition(rest, loc) : ifdef_value(name, rest, loc);
      conds.push_back({active, value, active && value, false, loc});
      return;
    }
    if (name == "elif" || name == "else" || name == "endif") {
      if (conds.empty()) {
        diags_.error(loc, "preprocessor", fmt::format("#{} without #if", name));
        return;
      }
      Cond& c = conds.back();
      if (name == "endif") {
        conds.pop_back();
      } else if (c.seen_else) {
        diags_.error(loc, "preprocessor", fmt::format("#{} after #else", name));
      } else if (name == "else") {
        c.seen_else = true;
        c.active = c.parent_active && !c.taken;
        c.taken = c.taken || c.active;
      } else {
        bool value = c.parent_active && !c.taken && eval_condition(rest, loc);
        c.active = value;
        c.taken = c.taken || value;
      }
      return;
    }
    if (!active) return; // unknown or other directives in skipped blocks are ignored
    if (name == "define") return define(rest, loc);
    if (name == "undef") {
      if (rest.empty() || rest[0].kind != TokKind::Ident)
        diags_.error(loc, "preprocessor", "#undef needs a macro name");
      else
        macros_.undefine(rest[0].text);
      return;
    }
    if (name == "include") return include(rest, loc, file, depth);
    if (name == "error") {
      std::string msg = "#error";
      for (const Token& t : rest) msg += fmt::format("{}{}", t.space_before ? " " : "", t.text);
      diags_.error(loc, "preprocessor", msg);
      return;
    }
    if (name == "pragma" || name == "line") return; // accepted and ignored
    diags_.error(name_tok.loc, "preprocessor", fmt::format("unknown directive '#{}'", name));
  }

  bool ifdef_value(std::string_view name, std::span<const Token> rest, ir::SourceLoc loc) {
    if (rest.empty() || rest[0].kind != TokKind::Ident) {
      diags_.error(loc, "preprocessor", fmt::format("#{} needs a macro name", name));
      return false;
    }
    return macros_.defined(rest[0].text) == (name == "ifdef");
  }

  bool eval_condition(std::span<const Token> rest, ir::SourceLoc loc) {
    // defined X / defined(X) are answered before macro expansion, as in C.
    static constexpr std::string_view one = "1", zero = "0";
    std::vector<Token> pre;
    for (size_t i = 0; i < rest.size(); ++i) {
      if (rest[i].kind == TokKind::Ident && rest[i].text == "defined") {
        size_t k = i + 1;
        bool paren = k < rest.size() && is_punct(rest[k], "(");
        if (paren) ++k;
        if (k >= rest.size() || rest[k].kind != TokKind::Ident ||
            (paren && (k + 1 >= rest.size() || !is_punct(rest[k + 1], ")")))) {
          diags_.error(rest[i].loc, "preprocessor", "'defined' needs a macro name");
          return false;
        }
        Token t = rest[i];
        t.kind = TokKind::Number;
        t.text = macros_.defined(rest[k].text) ? one : zero;
        pre.push_back(t);
        i = paren ? k + 1 : k;
      } else {
        pre.push_back(rest[i]);
      }
    }
    std::vector<Token> expanded;
    if (!macros_.expand(pre, expanded, diags_)) return false;
    auto v = detail::eval_pp_expression(expanded, loc, diags_);
    return v && *v != 0;
  }

  void define(std::span<const Token> rest, ir::SourceLoc loc) {
    if (rest.empty() || rest[0].kind != TokKind::Ident) {
      diags_.error(loc, "preprocessor", "#define needs a macro name");
      return;
    }
    Macro m;
    size_t i = 1;
    // "NAME(" with no space is a function-like macro; "NAME (" starts an object-like body.
    if (rest.size() > 1 && is_punct(rest[1], "(") && !rest[1].space_before) {
      m.function_like = true;
      i = 2;
      bool closed = false;
      while (i < rest.size()) {
        const Token& t = rest[i++];
        if (is_punct(t, ")")) {
          closed = true;
          break;
        }
        if (t.kind == TokKind::Ident && (m.params.empty() || is_punct(rest[i - 2], ","))) {
          m.params.push_back(t.text);
        } else if (!(is_punct(t, ",") && !m.params.empty() && !is_punct(rest[i - 2], ","))) {
          diags_.error(t.loc, "preprocessor", "bad macro parameter list");
          return;
        }
      }
      if (!closed) {
        diags_.error(rest[0].loc, "preprocessor", "missing ')' in macro parameter list");
        return;
      }
    }
    m.body.assign(rest.begin() + static_cast<ptrdiff_t>(i), rest.end());
    macros_.define(std::string(rest[0].text), std::move(m));
  }

  void include(std::span<const Token> rest, ir::SourceLoc loc, uint32_t file, int depth) {
    std::string target;
    if (rest.size() == 1 && rest[0].kind == TokKind::String) {
      target = std::string(rest[0].text.substr(1, rest[0].text.size() - 2));
    } else if (rest.size() >= 3 && is_punct(rest[0], "<") && is_punct(rest.back(), ">")) {
      for (const Token& t : rest.subspan(1, rest.size() - 2))
        target += fmt::format("{}{}", t.space_before && !target.empty() ? " " : "", t.text);
    } else {
      diags_.error(loc, "preprocessor", "#include expects \"file\" or <file>");
      return;
    }
    if (!options_.allow_include) {
      diags_.error(loc, "preprocessor", "#include is disabled for this input");
      return;
    }
    if (depth + 1 > kMaxIncludeDepth) {
      diags_.error(loc, "preprocessor",
                   fmt::format("#include nested deeper than {} levels", kMaxIncludeDepth));
      return;
    }
    auto path = find_include(target, file);
    if (!path) {
      diags_.error(loc, "preprocessor", missing_include_message(target, file));
      return;
    }
    std::error_code ec;
    fs::path canon = fs::weakly_canonical(*path, ec);
    if (ec) canon = *path;
    for (const fs::path& open : include_stack_)
      if (open == canon) {
        diags_.error(loc, "preprocessor",
                     fmt::format("#include cycle: '{}' includes itself", target));
        return;
      }
    std::error_code size_ec;
    if (fs::file_size(*path, size_ec) > kMaxIncludeBytes && !size_ec) {
      diags_.error(loc, "preprocessor", fmt::format("include file '{}' is too large", target));
      return;
    }
    std::ifstream in(*path, std::ios::binary);
    std::ostringstream buf;
    buf << in.rdbuf();
    if (!in) {
      diags_.error(loc, "preprocessor", fmt::format("cannot read include file '{}'", target));
      return;
    }
    uint32_t id = sm_.add(path->string(), buf.str());
    sm_.files[id].included = true;
    include_stack_.push_back(canon);
    process_file(id, depth + 1);
    include_stack_.pop_back();
  }

  // Why find_include found nothing: no such file, or one that exists but is no regular
  // file (a device such as /dev/zero, a FIFO, a folder), which "cannot find" would hide.
  std::string missing_include_message(const std::string& target, uint32_t from) {
    std::error_code ec;
    std::vector<fs::path> dirs{fs::path(sm_.files[from].name).parent_path()};
    for (const std::string& d : options_.include_dirs) dirs.emplace_back(d);
    for (const fs::path& d : dirs) {
      const fs::file_status st = fs::status(d / target, ec);
      if (!ec && fs::exists(st) && !fs::is_regular_file(st))
        return fmt::format("include file '{}' is not a regular file ({}); #include reads files "
                           "only",
                           target,
                           fs::is_directory(st) ? "a folder"
                           : fs::is_fifo(st)    ? "a FIFO"
                                                : "a device or special file");
    }
    return fmt::format("cannot find include file '{}'", target);
  }

  // Listings written on Windows name their headers "..\common\light.inl". A backslash is
  // an ordinary file-name byte on POSIX, so the name is first tried as written and then
  // with every backslash read as a directory separator.
  std::optional<fs::path> find_include(const std::string& target, uint32_t from) {
    std::error_code ec;
    std::vector<fs::path> dirs{fs::path(sm_.files[from].name).parent_path()};
    for (const std::string& d : options_.include_dirs) dirs.emplace_back(d);
    std::vector<std::string> spellings{target};
    if (target.find('\\') != std::string::npos) {
      std::string slashed = target;
      std::replace(slashed.begin(), slashed.end(), '\\', '/');
      spellings.push_back(slashed);
    }
    for (const std::string& name : spellings)
      for (const fs::path& d : dirs) {
        fs::path p = d / name;
        if (fs::is_regular_file(p, ec)) return p;
      }
    return std::nullopt;
  }

  ir::SourceManager& sm_;
  ir::DiagnosticSink& diags_;
  const ParseOptions& options_;
  TokenStream& out_;
  size_t first_error_;
  detail::MacroTable macros_;
  std::vector<fs::path> include_stack_;
};

} // namespace

TokenStream preprocess(uint32_t file, ir::SourceManager& sm, ir::DiagnosticSink& diags,
                       const ParseOptions& options) {
  TokenStream out;
  if (file >= sm.files.size()) {
    diags.error({}, "preprocessor", "no such source file");
    out.tokens.push_back({});
    return out;
  }
  Preprocessor pp(sm, diags, options, out);
  pp.run(file);
  return out;
}

} // namespace tierlift::assembly
