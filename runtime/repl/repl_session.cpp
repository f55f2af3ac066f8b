#include "runtime/repl/repl_session.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <exception>
#include <fstream>
#include <sstream>

#include "core/device/page/atomic_file.hpp"
#include "core/device/page/page_plot.hpp"
#include "core/format_number.hpp"
#include "core/hlr/render_frame.hpp"
#include "lang/parser.hpp"
#include "runtime/base/eval_error.hpp"
#include "runtime/base/interrupt.hpp"
#include "runtime/builtins/builtins.hpp"
#include "runtime/builtins/help_text.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/eval/program.hpp"
#include "runtime/pipeline/output_settings.hpp"
#include "runtime/pipeline/script_run.hpp"
#include "runtime/repl/repl_detail.hpp"
#include "runtime/values/format_value.hpp"

namespace hlr::runtime {

namespace fs = std::filesystem;
using repl::done;
using repl::error;
using repl::Extent;
using repl::point_text;
using repl::trim;

namespace {

constexpr const char* kValueName = "__repl_value";

// The parser stopped at the end of the input: an open brace, a trailing operator, a missing operand.
bool incomplete(const std::string& text, const lang::ParseResult& r) {
  if (r.ok() || r.diagnostics.empty()) return false;
  const lang::Diagnostic& d = r.diagnostics.front();
  if (d.message.rfind("unterminated string", 0) == 0) return false;  // strings end at the line's end
  return d.span.begin >= text.find_last_not_of(" \t\r\n") + 1;
}

std::string diagnostics_text(const lang::ParseResult& r) {
  std::string out;
  for (const lang::Diagnostic& d : r.diagnostics) out += lang::format(d, *r.source);
  return out;
}

std::string diagnostics_text(const std::vector<lang::Diagnostic>& ds, const Program& program) {
  std::ostringstream out;
  print_diagnostics(out, ds, program.sources());
  return out.str();
}

// A value as the REPL shows it: solids by their size, everything else as str() prints it.
std::string describe(const Value& v) {
  if (v.is(ValueKind::Solid)) {
    const Solid& s = *v.as_solid().solid;
    Extent e;
    e.add(s);
    return "solid " + v.as_solid().name + ": " + std::to_string(s.faces.size()) + " faces, " +
           std::to_string(s.edges.size()) + " edges, " + std::to_string(s.vertices.size()) + " vertices, " +
           (e.empty() ? "empty" : "bounds " + point_text(e.lo) + " to " + point_text(e.hi)) +
           (s.closed ? ", closed" : ", open");
  }
  if (v.is(ValueKind::Group)) return "group of " + std::to_string(v.as_group().size()) + " solids";
  try {
    return display(v, 2000);
  } catch (const FormatError&) {
    return "(a " + std::string(v.is_sequence() ? "long list" : "value") + ")";
  }
}

void names_of(const lang::Script& script, std::vector<std::string>& names,
              std::vector<std::string>& cameras) {
  for (const lang::Stmt& s : script.statements) {
    if (const auto* let = std::get_if<lang::LetStmt>(&s.node)) names.push_back(let->name.text);
    if (const auto* def = std::get_if<lang::DefStmt>(&s.node)) names.push_back(def->name.text);
    if (const auto* solid = std::get_if<lang::SolidStmt>(&s.node)) names.push_back(solid->name.text);
    if (const auto* camera = std::get_if<lang::CameraStmt>(&s.node)) cameras.push_back(camera->name.text);
  }
}

bool overlaps(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  for (const std::string& x : a)
    if (std::find(b.begin(), b.end(), x) != b.end()) return true;
  return false;
}

// Evaluates frame `frame` of `program` (frame 0 first: it says how many frames there are).
FrameScene evaluate_frame(const Program& program, int frame,
                          const std::function<void(const Evaluator&)>& inspect = nullptr) {
  FrameScene first = program.evaluate_first_frame(frame == 0 ? inspect : nullptr);
  if (frame == 0) return first;
  const int count = first.animation ? first.animation->frames : 1;
  if (frame >= count)
    throw RunError("the session has " + std::to_string(count) + (count == 1 ? " frame" : " frames") +
                       "; frame " + std::to_string(frame) + " is past the end",
                   ":frame 0 goes back to the first", 64);
  return program.evaluate(frame_time(frame, count, first.animation->fps), inspect);
}

}  // namespace

ReplSession::ReplSession(TerminalSize size) : size_(size) {}

std::string ReplSession::join(const std::vector<Chunk>& chunks) const {
  std::string text;
  for (const Chunk& c : chunks) {
    text += c.text;
    if (text.empty() || text.back() != '\n') text += '\n';
  }
  return text;
}

namespace {
std::unique_ptr<Program> session_program(const std::string& text, const std::optional<fs::path>& loaded,
                                         const AccessOptions& access, const Limits& limits) {
  const fs::path where = loaded ? fs::absolute(*loaded) : fs::current_path() / "session.hls";
  auto program = Program::from_text("<session>", text, where, access);
  program->set_limits(limits);
  return program;
}
}  // namespace

ReplReply ReplSession::feed(const std::string& line) {
  // The statements change only once an input succeeded; the view settings a command tries are put back.
  State before = state();
  const std::size_t changes = undo_.size();
  try {
    return feed_line(line);
  } catch (const RenderCancelled&) {
    restore(std::move(before));
    undo_.resize(std::min(undo_.size(), changes));
    pending_.clear();
    return error("stopped (Ctrl-C); the session is as it was");
  }
}

ReplReply ReplSession::feed_line(const std::string& line) {
  if (pending_.empty()) {
    const std::string t = trim(line);
    if (t.empty()) return done("");
    if (t[0] == ':') return command(t);
  }
  const std::string text = pending_ + line + "\n";
  const lang::ParseResult parsed = lang::parse(text, "<input>");
  if (parsed.ok()) {
    std::vector<lang::Diagnostic> syntax;
    lang::check_syntax(*parsed.script, syntax);
    pending_.clear();
    if (!syntax.empty()) {
      std::string out;
      for (const lang::Diagnostic& d : syntax) out += lang::format(d, *parsed.source);
      return error(out);
    }
    return accept(text);
  }
  if (incomplete(text, parsed)) {
    pending_ = text;
    return {ReplReply::Kind::More, ""};
  }
  pending_.clear();
  // Not a statement: an expression alone shows its value.
  const lang::ParseResult as_value = lang::parse(std::string("let ") + kValueName + " = " + text, "<input>");
  if (as_value.ok()) return evaluate_expression(text);
  return error(diagnostics_text(parsed));
}

ReplReply ReplSession::accept(const std::string& text) {
  const lang::ParseResult parsed = lang::parse(text, "<input>");
  Chunk chunk{text, {}, {}};
  names_of(*parsed.script, chunk.names, chunk.cameras);
  // A replacement goes where the old definition was, so what used it still can; if the new one needs
  // names defined after that place, at the end instead.
  std::string replaced;
  std::vector<Chunk> in_place, at_end;
  bool placed = false;
  for (const Chunk& old : chunks_) {
    if (overlaps(old.names, chunk.names) || overlaps(old.cameras, chunk.cameras)) {
      replaced += "replaced: " + trim(old.text.substr(0, old.text.find('\n'))) + "\n";
      if (!placed) in_place.push_back(chunk);
      placed = true;
      continue;
    }
    in_place.push_back(old);
    at_end.push_back(old);
  }
  at_end.push_back(chunk);
  if (!placed) in_place = at_end;
  // One evaluation per arrangement tried: the values shown come from the one that works.
  std::string values;
  auto attempt = [&](const std::vector<Chunk>& chunks, std::unique_ptr<Program>& program) {
    program = session_program(join(chunks), loaded_, access_, limits_);
    values.clear();
    return evaluate_frame(*program, frame_, [&](const Evaluator& e) {
      for (const std::string& name : chunk.names)
        if (const Value* v = e.global(name)) values += name + " = " + describe(*v) + "\n";
    });
  };
  std::vector<Chunk> next = in_place;
  std::unique_ptr<Program> program;  // the arrangement evaluated (its sources print the errors)
  try {
    FrameScene scene;
    try {
      scene = attempt(next, program);
    } catch (const std::exception&) {
      if (!placed) throw;
      const std::exception_ptr in_place_error = std::current_exception();
      std::unique_ptr<Program> other;
      try {
        scene = attempt(at_end, other);
      } catch (const std::exception&) {
        std::rethrow_exception(in_place_error);  // neither works: the in-place error says why
      }
      next = at_end;
      program = std::move(other);
    }
    std::string out = diagnostics_text(scene.warnings, *program) + replaced + values;
    for (const std::string& c : chunk.cameras) out += "camera " + c + "\n";
    if (text.find("draw") != std::string::npos) {
      std::size_t faces = 0;
      for (const SceneObject& o : scene.scene.objects) faces += o.solid->faces.size();
      out += "scene: " + std::to_string(scene.scene.objects.size()) + " objects, " + std::to_string(faces) +
             " faces\n";
    }
    remember("'" + trim(text.substr(0, text.find('\n'))) + "'", state());
    chunks_ = std::move(next);
    return done(out);
  } catch (const EvalError& e) {
    return error(e.diagnostics.empty() ? e.what() : diagnostics_text(e.diagnostics, *program));
  } catch (const RunError& e) {
    return error(std::string(e.what()) + (e.hint.empty() ? "" : "\nhint: " + e.hint));
  }
}

ReplReply ReplSession::evaluate_expression(const std::string& text) {
  // The expression on a line of its own, so that a message quotes only what was typed, at its columns.
  const auto program =
      session_program(join(chunks_) + "let " + kValueName + " =\n" + text, loaded_, access_, limits_);
  if (!program->parsed()) return error(diagnostics_text(program->syntax_errors(), *program));
  try {
    std::string shown;
    evaluate_frame(*program, frame_, [&](const Evaluator& e) {
      if (const Value* v = e.global(kValueName)) shown = describe(*v);
    });
    return done(shown + "\n");
  } catch (const EvalError& e) {
    return error(e.diagnostics.empty() ? e.what() : diagnostics_text(e.diagnostics, *program));
  } catch (const RunError& e) {
    return error(e.what());
  }
}

std::optional<ReplSession::View> ReplSession::view(std::string& message) const {
  const auto program = session_program(view_text(chunks_), loaded_, access_, limits_);
  View v;
  try {
    v.scene = evaluate_frame(*program, frame_);
    if (v.scene.cameras.empty() && v.scene.views.empty()) {  // a sheet's view is looked through too
      message =
          "nothing to look through yet: the session declares no camera\n"
          "hint: camera main = lookat(eye: (30, 20, 15), target: (0, 0, 0))\n";
      return std::nullopt;
    }
    const NamedCamera& c = choose_camera(v.scene, drawn_camera(), "the session");
    v.camera = c.name;
    // Framed as `:render` frames it on the session's paper, so the terminal shows what the file will.
    v.view_camera = framed_camera(c.camera, page_spec_for(v.scene, DeviceOptions{}));
    HlrOptions o;
    const HiddenStyle hidden = hidden_.value_or(v.scene.hidden.value_or(HiddenStyle::off()));
    o.include_hidden = hidden.drawn();  // the picture draws every level as a hidden line
    o.max_level = hidden.max_level();
    o.cancel = &interrupt_requested();
    const auto start = std::chrono::steady_clock::now();
    v.result = render_frame(v.scene.scene, v.view_camera, o);
    v.render_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return v;
  } catch (const EvalError& e) {
    message = e.diagnostics.empty() ? e.what() : diagnostics_text(e.diagnostics, *program);
  } catch (const RunError& e) {
    message = std::string(e.what()) + (e.hint.empty() ? "\n" : "\nhint: " + e.hint + "\n");
  }
  return std::nullopt;
}

ReplReply ReplSession::show() {
  std::string message;
  const std::optional<View> v = view(message);
  if (!v) return error(message);
  std::string out;
  if (graphics_ != TerminalGraphics::Braille) {
    try {
      out =
          terminal_image(v->result.segments, v->view_camera.frame, graphics_, pixels_.width, pixels_.height);
    } catch (const std::runtime_error&) {
      out.clear();  // cairo could not draw it: the braille picture says the same
    }
  }
  if (out.empty())
    out =
        braille_picture(v->result.segments, v->view_camera.frame, size_.columns, std::max(1, size_.rows - 2));
  out += "camera " + v->camera + ", frame " + std::to_string(frame_) + ": " +
         std::to_string(v->result.stats.visible_segments) + " visible pieces\n";
  return done(out);
}

ReplReply ReplSession::stats() {
  std::string message;
  const std::optional<View> v = view(message);
  if (!v) return error(message);
  std::size_t faces = 0, edges = 0;
  for (const SceneObject& o : v->scene.scene.objects) {
    faces += o.solid->faces.size();
    edges += o.solid->edges.size();
  }
  PagePlotOptions plot;
  plot.spec = page_spec_for(v->scene, DeviceOptions{});
  plot.hidden = hidden_.value_or(v->scene.hidden.value_or(HiddenStyle::off()));
  const PagePlot page = plot_page(v->result.segments, v->view_camera.frame, "", plot);
  const PlanStats& s = page.stats;
  char line[512];
  std::snprintf(
      line, sizeof line,
      "frame %d, camera %s: %zu objects, %zu faces, %zu edges; %zu candidate edges, %zu visible pieces "
      "(%.2f ms)\npen plan on A4: pen-down %.1f mm, pen-up %.1f mm, %zu lifts (lower bound %zu)\n",
      frame_, v->camera.c_str(), v->scene.scene.objects.size(), faces, edges, v->result.stats.candidate_edges,
      v->result.stats.visible_segments, v->render_ms, s.pen_down_mm, s.pen_up_mm, s.lifts,
      s.lift_lower_bound);
  return done(line);
}

ReplReply ReplSession::scene() {
  const auto program = session_program(join(chunks_), loaded_, access_, limits_);
  try {
    const FrameScene s = evaluate_frame(*program, frame_);
    std::string out;
    for (const SceneObject& o : s.scene.objects)
      out += "  " + o.name + ": " + std::to_string(o.solid->faces.size()) + " faces, " +
             std::to_string(o.solid->edges.size()) + " edges\n";
    if (out.empty()) out = "  nothing drawn yet\n";
    std::string cameras;
    for (const NamedCamera& c : s.cameras) cameras += (cameras.empty() ? "" : ", ") + c.name;
    out += "cameras: " + (cameras.empty() ? std::string("none") : cameras) +
           (camera_ ? " (drawing with " + *camera_ + ")" : "") + "; frame " + std::to_string(frame_) +
           (s.animation ? " of " + std::to_string(s.animation->frames) : "") + "\n";
    return done(out);
  } catch (const EvalError& e) {
    return error(e.diagnostics.empty() ? e.what() : diagnostics_text(e.diagnostics, *program));
  } catch (const RunError& e) {
    return error(e.what());
  }
}

ReplReply ReplSession::frames() {
  const auto program = session_program(join(chunks_), loaded_, access_, limits_);
  try {
    const FrameScene first = evaluate_frame(*program, 0);
    if (!first.animation) return done("one frame (no animate statement); :frame 0 is the drawing\n");
    const int n = first.animation->frames;
    return done(std::to_string(n) + " frames at " + format_number(first.animation->fps) +
                " fps (frame 0 to " + std::to_string(n - 1) + "); looking at frame " +
                std::to_string(frame_) + ", :frame N for another\n");
  } catch (const EvalError& e) {
    return error(e.diagnostics.empty() ? e.what() : diagnostics_text(e.diagnostics, *program));
  }
}

namespace {

// The text of the camera expression `name` is declared with (the last declared for nullopt), searching
// the chunks' top-level statements from the end.
template <typename Chunks>
std::optional<std::string> camera_expression(const Chunks& chunks, const std::optional<std::string>& name) {
  for (auto chunk = chunks.rbegin(); chunk != chunks.rend(); ++chunk) {
    const lang::ParseResult parsed = lang::parse(chunk->text, "<input>");
    if (!parsed.ok()) continue;
    for (auto stmt = parsed.script->statements.rbegin(); stmt != parsed.script->statements.rend(); ++stmt) {
      const auto* camera = std::get_if<lang::CameraStmt>(&stmt->node);
      if (!camera || (name && camera->name.text != *name)) continue;
      const lang::SourceSpan& span = camera->value->span;
      return chunk->text.substr(span.begin, span.end - span.begin);
    }
  }
  return std::nullopt;
}

// Makes every top-level `style hidden` statement of the chunks say `style`; false when there is none.
// Dashed or levels keep the statement's pen clause (levels count from it); off drops it (a pen there is an
// error).
template <typename Chunks>
bool set_hidden_style(Chunks& chunks, const HiddenStyle& style) {
  bool found = false;
  for (auto& chunk : chunks) {
    const lang::ParseResult parsed = lang::parse(chunk.text, "<input>");
    if (!parsed.ok()) continue;
    std::string text = chunk.text;
    const auto& statements = parsed.script->statements;
    for (auto stmt = statements.rbegin(); stmt != statements.rend(); ++stmt) {  // from the end: spans hold
      const auto* style_stmt = std::get_if<lang::StyleStmt>(&stmt->node);
      if (!style_stmt || style_stmt->property.text != "hidden") continue;
      found = true;
      // Up to the pen clause, kept (N may be `(…)`, whose node spans only what is inside), or the whole
      // statement for off and for a statement without a pen.
      const bool keep_pen = style.drawn() && style_stmt->pen;
      const std::size_t end = keep_pen ? style_stmt->pen->span.begin : stmt->span.end;
      text.replace(stmt->span.begin, end - stmt->span.begin,
                   "style hidden " + style.words() + (keep_pen ? " " : ""));
    }
    chunk.text = std::move(text);
  }
  return found;
}

}  // namespace

std::string ReplSession::script() const {
  std::vector<Chunk> chunks = chunks_;
  std::string tail;
  // :hidden wins over the session's own style statement, which would otherwise be set twice.
  if (hidden_ && !set_hidden_style(chunks, *hidden_)) tail += "style hidden " + hidden_->words() + "\n";
  std::string text;
  if (step_) {
    text = view_text(chunks);  // the adjusted camera, declared last, draws
  } else if (camera_) {
    // The chosen camera draws when it is declared last: its statement moved there when it declares
    // nothing else, else the camera declared again there.
    const auto it = std::find_if(chunks.begin(), chunks.end(), [&](const Chunk& c) {
      return c.cameras == std::vector<std::string>{*camera_} && c.names.empty() &&
             c.text.find('\n') + 1 == c.text.size();
    });
    if (it != chunks.end()) {
      const Chunk moved = *it;
      chunks.erase(it);
      chunks.push_back(moved);
      text = join(chunks);
    } else if (const std::optional<std::string> expr = camera_expression(chunks, camera_)) {
      text = join(chunks) + "camera drawn_" + *camera_ + " = " + *expr + "\n";
    } else {
      text = join(chunks) + "# drawn in the session with camera " + *camera_ + ": hlrscript FILE --camera " +
             *camera_ + "\n";
    }
  } else {
    text = join(chunks);
  }
  return "# Saved from an hlrscript session.\n" + text + tail;
}

ReplReply ReplSession::save(const std::string& file) {
  if (file.empty()) return error(":save needs a file name, as in :save scene.hls");
  try {
    const std::string text = script();
    write_atomically(file, [&](const fs::path& temp) {
      std::ofstream out(temp, std::ios::binary);
      out << text;
      out.close();
      if (!out) throw std::runtime_error("write failed");
    });
  } catch (const DeviceError& e) {
    return error(e.what());
  }
  const std::size_t n = chunks_.size();
  return done("saved the session to " + file + " (" + std::to_string(n) + (n == 1 ? " input" : " inputs") +
              ")\n");
}

ReplReply ReplSession::render(const std::string& file) {
  const auto program = session_program(view_text(chunks_), loaded_, access_, limits_);
  if (!file.empty() && !device_kind_for(file))
    return error(":render " + file + ": unknown output type '" + fs::path(file).extension().string() +
                 "'; supported: " + supported_extensions());
  RunOptions o;
  o.from_repl = true;  // the REPL's Ctrl-C handler stays; a stop is reported as the REPL's
  o.script = "<session>";
  o.title = loaded_ ? loaded_->filename().string() : std::string("hlrscript session");
  if (!file.empty()) o.output = file;
  o.camera = drawn_camera();
  o.hidden = hidden_;
  std::ostringstream out, err;
  const int code = run_loaded_program(*program, o, out, err);
  return code == 0 ? done(err.str() + out.str()) : error(err.str() + out.str());
}

ReplReply ReplSession::load(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return error("cannot read '" + path.string() + "'");
  std::ostringstream s;
  s << in.rdbuf();
  const std::string text = s.str();
  const lang::ParseResult parsed = lang::parse(text, path.string());
  if (!parsed.ok()) return error(diagnostics_text(parsed));
  Chunk chunk{text, {}, {}};
  names_of(*parsed.script, chunk.names, chunk.cameras);
  const auto program = session_program(text, path, access_, limits_);
  try {
    const FrameScene scene = evaluate_frame(*program, 0);
    remember(":load " + path.string(), state());
    chunks_ = {chunk};
    loaded_ = path;
    frame_ = 0;
    camera_.reset();  // the cameras are the new script's
    step_.reset();
    std::size_t faces = 0;
    for (const SceneObject& o : scene.scene.objects) faces += o.solid->faces.size();
    return done(diagnostics_text(scene.warnings, *program) + "loaded " + path.string() + ": " +
                std::to_string(scene.scene.objects.size()) + " objects, " + std::to_string(faces) +
                " faces, " + std::to_string(scene.cameras.size()) + " cameras\n");
  } catch (const EvalError& e) {
    return error(e.diagnostics.empty() ? e.what() : diagnostics_text(e.diagnostics, *program));
  }
}

std::optional<std::string> ReplSession::drawn_camera() const {
  if (step_) return stepped_name_;
  return camera_;
}

std::string ReplSession::view_text(const std::vector<Chunk>& chunks) const {
  std::string text = join(chunks);
  if (!step_) return text;
  // The expression of the camera being stepped: the chosen one, else the last declared.
  const std::optional<std::string> expr = camera_expression(chunks, camera_);
  if (!expr) return text;
  const CameraAdjustment& a = *step_;
  return text + "camera " + stepped_name_ + " = adjust(" + *expr + ", theta: " + format_number(a.theta_deg) +
         ", phi: " + format_number(a.phi_deg) + ", zoom: " + format_number(a.zoom) +
         ", dolly: " + format_number(a.dolly) + ", pivot: " + point_text(a.pivot) + ")\n";
}

void ReplSession::restore(State s) {
  chunks_ = std::move(s.chunks);
  frame_ = s.frame;
  hidden_ = s.hidden;
  camera_ = std::move(s.camera);
  step_ = s.step;
  stepped_name_ = std::move(s.stepped_name);
  loaded_ = std::move(s.loaded);
}

}  // namespace hlr::runtime
