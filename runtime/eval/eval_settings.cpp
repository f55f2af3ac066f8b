// Settings statements (animate, output, style) and include; paper, pen and plotter are in
// eval_devices.cpp. Each setting may be given once per evaluation; a second one is an error pointing at
// the first, so two files cannot silently disagree.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <tuple>
#include <vector>

#include "core/format_number.hpp"
#include "core/limits.hpp"
#include "runtime/eval/eval_detail.hpp"
#include "runtime/eval/evaluator.hpp"

namespace hlr::runtime {

void Evaluator::already_set(const lang::SourceSpan& span, const std::string& what,
                            const lang::SourceSpan& first) {
  lang::Diagnostic d;
  d.span = span;
  d.message = "'" + what + "' is already set";
  d.hint = "keep one '" + what + "' statement";
  d.notes.push_back({first, "it was set here"});
  throw EvalError(std::move(d));
}

double Evaluator::eval_number(const lang::Expr& expr, const ScopePtr& scope, const std::string& what) {
  const Value v = eval(expr, scope);
  if (!v.is(ValueKind::Number))
    fail(expr.span, what + " must be a number, got " + kind_with_article(v.kind()));
  return v.as_number();
}

void Evaluator::exec_animate(const lang::AnimateStmt& animate, const lang::Stmt& stmt,
                             const ScopePtr& scope) {
  if (out_.animation) already_set(stmt.span, "animate", out_.animation->span);
  const double frames = eval_number(*animate.frames, scope, "the frame count");
  if (frames > static_cast<double>(kMaxFrames))
    fail(animate.frames->span, limit_message("frames", kMaxFrames) + ": got " + format_for_message(frames),
         "split a long sequence into several scripts or render at a lower frame rate");
  if (!(frames >= 1) || std::floor(frames) != frames)
    fail(animate.frames->span, "the frame count must be a whole number from 1 to " +
                                   std::to_string(kMaxFrames) + ", got " + format_for_message(frames));
  AnimationSetting a;
  a.frames = static_cast<int>(frames);
  a.span = stmt.span;
  if (animate.fps) {
    a.fps = eval_number(*animate.fps, scope, "fps");
    if (!(a.fps > 0)) fail(animate.fps->span, "fps must be positive, got " + format_for_message(a.fps));
  }
  out_.animation = a;
}

void Evaluator::exec_output(const lang::OutputStmt& output, const lang::Stmt& stmt, const ScopePtr& scope) {
  if (out_.output) already_set(stmt.span, "output", out_.output->span);
  const Value name = eval(*output.pattern, scope);
  if (!name.is(ValueKind::String))
    fail(output.pattern->span, "the output name must be a string, got " + kind_with_article(name.kind()));
  if (name.as_string().empty()) fail(output.pattern->span, "the output name is empty");
  OutputSetting o;
  o.name = name.as_string();
  const auto* lit = std::get_if<lang::StringLit>(&output.pattern->node);
  o.interpolated = lit && !lit->is_plain();
  o.span = output.pattern->span;
  // `plotter NAME` is only recorded: the run resolves it against the declared and built-in profiles.
  if (output.plotter) {
    if (output.plotter->text.empty()) fail(output.plotter->span, "the plotter name is empty");
    o.plotter = output.plotter->text;
    o.plotter_span = output.plotter->span;
  }
  out_.output = o;
  if (output.paper.size) set_paper(output.paper, stmt, scope);
}

void Evaluator::exec_style(const lang::StyleStmt& style, const lang::Stmt& stmt, const ScopePtr& scope) {
  if (style.property.text != "hidden")
    fail(style.property.span, "unknown style '" + style.property.text + "'",
         "the style is: style hidden dashed|off|levels N [pen P]");
  if (out_.hidden_span) already_set(stmt.span, "style hidden", *out_.hidden_span);
  const std::string& value = style.value.text;
  if (value != "dashed" && value != "off" && value != "levels")
    fail(style.value.span, "style hidden takes 'dashed', 'off' or 'levels N', got '" + value + "'");
  if (style.pen && value == "off")  // the syntax check reports it first
    fail(style.pen->span, "a pen goes only with 'style hidden dashed' or 'style hidden levels N'");
  HiddenStyle hidden = value == "dashed" ? HiddenStyle::dashed() : HiddenStyle::off();
  if (value == "levels") {
    if (!style.levels)
      fail(style.value.span, "'levels' needs a number of levels, as in 'style hidden levels 3'");
    const double n = eval_number(*style.levels, scope, "the number of levels");
    if (!(n >= 1 && n <= kMaxOcclusionLevel) || std::floor(n) != n)
      fail(style.levels->span,
           "the number of levels must be a whole number from 1 to " + std::to_string(kMaxOcclusionLevel) +
               ", got " + format_for_message(n),
           "level k is the hidden pieces behind k surfaces: 'style hidden levels 3' draws levels 1, 2 and 3");
    hidden = HiddenStyle::counted(static_cast<int>(n));
  }
  if (style.pen) {
    const int pen = eval_pen_number(*style.pen->number, scope);
    // Level k is drawn in pen P + k − 1: the last level's pen must exist too.
    if (hidden.counts_levels() && pen + hidden.levels - 1 > kMaxPen)
      fail(style.pen->span,
           "levels 1.." + std::to_string(hidden.levels) + " from pen " + std::to_string(pen) +
               " need pens up to " + std::to_string(pen + hidden.levels - 1) + ", past the last pen, " +
               std::to_string(kMaxPen),
           "level k is drawn in pen P + k - 1: start from pen " +
               std::to_string(kMaxPen - hidden.levels + 1) + " or lower, or draw fewer levels");
    out_.hidden_pen = pen;
  }
  out_.hidden = hidden;
  out_.hidden_span = stmt.span;
}

IncludeTarget include_target(const SourceTable& sources, const lang::IncludeStmt& include) {
  namespace fs = std::filesystem;
  const SourceEntry* from = sources.entry(include.path_span.file);
  const fs::path base = from ? from->path.parent_path() : fs::current_path();
  const fs::path shown_base = from ? fs::path(from->source->name()).parent_path() : fs::path();
  // "std/NAME.hls" names a library module written in hlrscript (stdlib/modules/); any other path is
  // relative to the including file.
  IncludeTarget t;
  t.library = include.path.rfind("std/", 0) == 0;
  t.path = t.library                              ? stdlib_module_directory() / include.path.substr(4)
           : fs::path(include.path).is_absolute() ? fs::path(include.path)
                                                  : base / include.path;
  t.shown = t.library || fs::path(include.path).is_absolute()
                ? include.path
                : (shown_base / include.path).lexically_normal().string();
  // Checked before the file is opened: a file the script may not read is never read, so no message can
  // quote it. Only scripts are included; anything else (a mesh, a key, a log) is not even parsed.
  const FileAccess& access = sources.access();
  std::string extension = t.path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (const std::optional<std::string> refusal = access.read_refusal(t.path, include.path)) {
    t.refusal = "cannot include " + *refusal;
    t.hint = access.allow_hint(t.path);
  } else if (extension != ".hls") {
    t.refusal = "cannot include '" + include.path + "': include reads hlrscript scripts (.hls) only";
    t.hint =
        "include takes scripts ending in .hls; a mesh file is read with import(\"" + include.path + "\")";
    t.refusal_kind = ErrorKind::Script;
  }
  return t;
}

void Evaluator::exec_include(const lang::IncludeStmt& include, const ScopePtr& scope) {
  const SourceEntry* from = sources_.entry(include.path_span.file);
  if (include.path.empty()) fail(include.path_span, "the include path is empty");
  const IncludeTarget t = include_target(sources_, include);
  const auto& [target, shown, library] = std::tie(t.path, t.shown, t.library);
  if (!t.refusal.empty()) {
    lang::Diagnostic d;
    d.span = include.path_span;
    d.message = t.refusal;
    d.hint = t.hint;
    throw EvalError(std::move(d), t.refusal_kind);
  }

  std::string error;
  const SourceEntry* entry = sources_.load(target, shown, error);
  if (!entry) {
    lang::Diagnostic d;
    d.span = include.path_span;
    d.message = error;
    if (library) {
      // The modules there, as an include names them, and the likeliest one.
      std::vector<std::string> modules;
      for (const std::filesystem::path& file : library_module_files())
        modules.push_back("std/" + file.filename().string());
      const std::string guess = did_you_mean(include.path, modules);
      std::error_code missing;
      if (!std::filesystem::exists(target, missing))
        d.message = "no library module '" + include.path + "'" + (guess.empty() ? "" : " (" + guess + ")");
      std::string list;
      for (const std::string& m : modules) list += (list.empty() ? "" : ", ") + m;
      d.hint = (modules.empty()
                    ? "no library modules in " + stdlib_module_directory().string()
                    : "the library modules: " + list + " (in " + stdlib_module_directory().string() + ")") +
               "; HLRSCRIPT_STDLIB overrides the folder";
    } else {
      d.hint =
          "include paths are relative to the including file ('" + (from ? from->source->name() : "") + "')";
    }
    throw EvalError(std::move(d), ErrorKind::Input);
  }
  if (!entry->script) throw EvalError(entry->diagnostics, ErrorKind::Script, "syntax errors in " + shown);
  for (const lang::FileId id : include_stack_)
    if (id == entry->id) {
      std::string chain;
      for (const lang::FileId f : include_stack_) chain += sources_.file(f)->name() + " → ";
      fail(include.path_span, "include cycle: " + chain + shown,
           "a file must not include itself, even indirectly");
    }
  if (included_.count(entry->id)) return;  // each file once per evaluation
  if (include_stack_.size() >= kMaxIncludeDepth)
    fail(include.path_span, limit_message("nested includes", kMaxIncludeDepth));
  include_stack_.push_back(entry->id);
  included_.insert(entry->id);
  // The included statements run in the including scope, as if written in place.
  run_statements(entry->script->statements, scope);
  include_stack_.pop_back();
}

}  // namespace hlr::runtime
