#include "runtime/repl_session.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <fstream>
#include <sstream>

#include "core/device/atomic_file.hpp"
#include "core/device/page_plot.hpp"
#include "core/format_number.hpp"
#include "core/hlr/render_frame.hpp"
#include "lang/parser.hpp"
#include "runtime/builtins.hpp"
#include "runtime/cli.hpp"
#include "runtime/eval_error.hpp"
#include "runtime/evaluator.hpp"
#include "runtime/format_value.hpp"
#include "runtime/output_settings.hpp"
#include "runtime/program.hpp"

namespace hlr::runtime {

namespace fs = std::filesystem;

namespace {

constexpr const char* kValueName = "__repl_value";

const std::vector<std::string> kKeywords = {"solid",  "let",     "def",     "for",    "if",    "else",
                                            "draw",   "camera",  "animate", "output", "paper", "style",
                                            "pen",    "plotter", "include", "at",     "then",  "in",
                                            "return", "vertex",  "face",    "hole",   "line"};

struct Command {
  const char* name;
  const char* usage;
  const char* help;
};
const Command kCommands[] = {
    {"help", ":help", "this list"},
    {"load", ":load FILE", "replace the session by a script (then :reload reads it again)"},
    {"reload", ":reload", "read the loaded script again"},
    {"show", ":show", "draw the current frame in the terminal"},
    {"render", ":render [FILE]", "write the session's frames to FILE (.pdf .svg .png .hpgl .steps .json)"},
    {"camera", ":camera [NAME]", "draw with camera NAME (no name: the last declared)"},
    {"orbit", ":orbit DTHETA [DPHI]",
     "step the camera round the scene (degrees; Albers' theta and phi keys)"},
    {"zoom", ":zoom F", "magnify the picture F times"},
    {"dolly", ":dolly D", "move the eye D scene units forward along the view"},
    {"frame", ":frame N", "look at frame N of the animation"},
    {"hidden", ":hidden on|off", "draw hidden lines dashed, or not"},
    {"stats", ":stats", "faces, edges, visible pieces, pen plan, render time of the current frame"},
    {"scene", ":scene", "what is drawn, with sizes, and the cameras"},
    {"undo", ":undo", "take back the last accepted input"},
    {"save", ":save FILE", "write the session as a script that renders the same drawing"},
    {"quit", ":quit", "leave (Ctrl-D too)"},
};

ReplReply done(std::string text) { return {ReplReply::Kind::Done, std::move(text)}; }
ReplReply error(std::string text) {
  if (!text.empty() && text.back() != '\n') text += '\n';
  return {ReplReply::Kind::Error, std::move(text)};
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

// The parser stopped at the end of the input: an open brace, a trailing operator, a missing operand.
bool incomplete(const std::string& text, const lang::ParseResult& r) {
  if (r.ok() || r.diagnostics.empty()) return false;
  const lang::Diagnostic& d = r.diagnostics.front();
  if (d.message.rfind("unterminated string", 0) == 0) return false;  // strings end at the line's end
  return d.span.begin.offset >= text.find_last_not_of(" \t\r\n") + 1;
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

std::string point_text(Point3 p) {
  return "(" + format_number(p.x) + ", " + format_number(p.y) + ", " + format_number(p.z) + ")";
}

// The box round solids' vertices.
struct Extent {
  Point3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  void add(const Solid& s) {
    for (const Point3& p : s.vertices) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  }
  bool empty() const { return lo.x > hi.x; }
  Point3 middle() const { return {(lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2}; }
};

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
  FrameScene first = program.evaluate(frame_time(0, 1, 24), frame == 0 ? inspect : nullptr);
  if (frame == 0) return first;
  const int count = first.animation ? first.animation->frames : 1;
  if (frame >= count)
    throw RunError("the session has " + std::to_string(count) + (count == 1 ? " frame" : " frames") +
                       "; frame " + std::to_string(frame) + " is past the end",
                   ":frame 0 goes back to the first", 64);
  return program.evaluate(frame_time(frame, count, first.animation->fps), inspect);
}

}  // namespace

struct ReplSession::View {
  FrameScene scene;
  std::string camera;
  Camera view_camera;
  FrameResult result;
  double render_ms = 0;
};

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
std::unique_ptr<Program> session_program(const std::string& text, const std::optional<fs::path>& loaded) {
  const fs::path where = loaded ? fs::absolute(*loaded) : fs::current_path() / "session.hls";
  return Program::from_text("<session>", text, where);
}
}  // namespace

ReplReply ReplSession::feed(const std::string& line) {
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
    program = session_program(join(chunks), loaded_);
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
    undo_.push_back(chunks_);
    chunks_ = std::move(next);
    return done(out);
  } catch (const EvalError& e) {
    return error(e.diagnostics.empty() ? e.what() : diagnostics_text(e.diagnostics, *program));
  } catch (const RunError& e) {
    return error(std::string(e.what()) + (e.hint.empty() ? "" : "\nhint: " + e.hint));
  }
}

ReplReply ReplSession::evaluate_expression(const std::string& text) {
  const auto program = session_program(join(chunks_) + "let " + kValueName + " = " + text, loaded_);
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
  const auto program = session_program(view_text(chunks_), loaded_);
  View v;
  try {
    v.scene = evaluate_frame(*program, frame_);
    if (v.scene.cameras.empty()) {
      message =
          "nothing to look through yet: the session declares no camera\n"
          "hint: camera main = lookat(eye: (30, 20, 15), target: (0, 0, 0))\n";
      return std::nullopt;
    }
    const NamedCamera& c = choose_camera(v.scene, drawn_camera(), "the session");
    v.camera = c.name;
    v.view_camera = c.camera;
    HlrOptions o;
    o.include_hidden = hidden_.value_or(v.scene.hidden.value_or(false));
    const auto start = std::chrono::steady_clock::now();
    v.result = render_frame(v.scene.scene, c.camera, o);
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
  std::string out =
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
  plot.include_hidden = hidden_.value_or(v->scene.hidden.value_or(false));
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
  const auto program = session_program(join(chunks_), loaded_);
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

std::string ReplSession::script() const {
  std::vector<Chunk> chunks = chunks_;
  std::string tail;
  if (camera_) {
    // The chosen camera is the one a script draws with when it is declared last.
    const auto it = std::find_if(chunks.begin(), chunks.end(), [&](const Chunk& c) {
      return c.cameras == std::vector<std::string>{*camera_} && c.names.empty();
    });
    if (it != chunks.end()) {
      const Chunk moved = *it;
      chunks.erase(it);
      chunks.push_back(moved);
    } else {
      tail +=
          "# drawn in the session with camera " + *camera_ + ": hlrscript FILE --camera " + *camera_ + "\n";
    }
  }
  if (hidden_) tail += *hidden_ ? "style hidden dashed\n" : "style hidden off\n";
  return "# Saved from an hlrscript session.\n" + view_text(chunks) + tail;
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
  return done("saved " + std::to_string(chunks_.size()) + " inputs to " + file + "\n");
}

ReplReply ReplSession::render(const std::string& file) {
  const auto program = session_program(view_text(chunks_), loaded_);
  CliOptions o;
  o.script = "<session>";
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
  const auto program = session_program(text, path);
  try {
    const FrameScene scene = evaluate_frame(*program, 0);
    undo_.push_back(chunks_);
    chunks_ = {chunk};
    loaded_ = path;
    frame_ = 0;
    std::size_t faces = 0;
    for (const SceneObject& o : scene.scene.objects) faces += o.solid->faces.size();
    return done(diagnostics_text(scene.warnings, *program) + "loaded " + path.string() + ": " +
                std::to_string(scene.scene.objects.size()) + " objects, " + std::to_string(faces) +
                " faces, " + std::to_string(scene.cameras.size()) + " cameras\n");
  } catch (const EvalError& e) {
    return error(e.diagnostics.empty() ? e.what() : diagnostics_text(e.diagnostics, *program));
  }
}

ReplReply ReplSession::command(const std::string& line) {
  std::istringstream words(line.substr(1));
  std::string name, arg;
  words >> name;
  std::getline(words >> std::ws, arg);
  arg = trim(arg);
  std::vector<const Command*> matches;
  for (const Command& c : kCommands) {
    if (name == c.name) {
      matches = {&c};
      break;
    }
    if (!name.empty() && std::string(c.name).rfind(name, 0) == 0) matches.push_back(&c);
  }
  if (matches.size() != 1) {
    std::string known;
    for (const Command* c : matches) known += std::string(known.empty() ? "" : ", ") + ":" + c->name;
    return error(matches.empty() ? "unknown command ':" + name + "'; :help lists them"
                                 : "':" + name + "' could be " + known);
  }
  const std::string cmd = matches.front()->name;
  if (cmd == "help") return done(repl_help_text());
  if (cmd == "quit") return {ReplReply::Kind::Quit, ""};
  if (cmd == "show") return show();
  if (cmd == "stats") return stats();
  if (cmd == "scene") return scene();
  if (cmd == "render") return render(arg);
  if (cmd == "save") return save(arg);
  if (cmd == "load") return arg.empty() ? error(":load needs a file name") : load(arg);
  if (cmd == "reload") return loaded_ ? load(*loaded_) : error("nothing loaded yet: :load FILE");
  if (cmd == "undo") {
    if (undo_.empty()) return error("nothing to undo");
    chunks_ = std::move(undo_.back());
    undo_.pop_back();
    return done("undone; the session has " + std::to_string(chunks_.size()) + " inputs\n");
  }
  if (cmd == "orbit" || cmd == "zoom" || cmd == "dolly") return step_camera(cmd, arg);
  if (cmd == "hidden") {
    if (arg != "on" && arg != "off") return error(":hidden needs on or off");
    hidden_ = arg == "on";
    return done(std::string("hidden lines ") + (*hidden_ ? "dashed" : "off") + "\n");
  }
  if (cmd == "camera") {
    if (arg.empty()) {
      camera_.reset();
      step_.reset();
      return done("drawing with the last camera declared\n");
    }
    const std::optional<std::string> before = camera_;
    const std::optional<CameraAdjustment> stepped = step_;
    camera_ = arg;
    step_.reset();  // a camera chosen anew starts where its statement puts it
    std::string message;
    if (!view(message)) {
      camera_ = before;
      step_ = stepped;
      return error(message);
    }
    return done("drawing with camera " + arg + "\n");
  }
  if (cmd == "frame") {
    char* end = nullptr;
    const long n = std::strtol(arg.c_str(), &end, 10);
    if (arg.empty() || *end != '\0' || n < 0 || n > 1'000'000)
      return error(":frame needs a frame number, as in :frame 3");
    const int before = frame_;
    frame_ = static_cast<int>(n);
    const ReplReply r = scene();
    if (r.kind == ReplReply::Kind::Error) frame_ = before;
    return r;
  }
  return error("unknown command");
}

std::optional<std::string> ReplSession::drawn_camera() const {
  if (step_) return stepped_name_;
  return camera_;
}

std::string ReplSession::view_text(const std::vector<Chunk>& chunks) const {
  std::string text = join(chunks);
  if (!step_) return text;
  // The expression of the camera being stepped: the chosen one, else the last declared.
  for (auto chunk = chunks.rbegin(); chunk != chunks.rend(); ++chunk) {
    const lang::ParseResult parsed = lang::parse(chunk->text, "<input>");
    if (!parsed.ok()) continue;
    for (auto stmt = parsed.script->statements.rbegin(); stmt != parsed.script->statements.rend(); ++stmt) {
      const auto* camera = std::get_if<lang::CameraStmt>(&stmt->node);
      if (!camera || (camera_ && camera->name.text != *camera_)) continue;
      const lang::SourceSpan& span = camera->value->span;
      const std::string expr = chunk->text.substr(span.begin.offset, span.end.offset - span.begin.offset);
      const CameraAdjustment& a = *step_;
      return text + "camera " + stepped_name_ + " = adjust(" + expr +
             ", theta: " + format_number(a.theta_deg) + ", phi: " + format_number(a.phi_deg) +
             ", zoom: " + format_number(a.zoom) + ", dolly: " + format_number(a.dolly) +
             ", pivot: " + point_text(a.pivot) + ")\n";
    }
  }
  return text;
}

ReplReply ReplSession::step_camera(const std::string& cmd, const std::string& arguments) {
  std::istringstream in(arguments);
  double x = 0, y = 0;
  const bool has_x = static_cast<bool>(in >> x);
  const bool has_y = static_cast<bool>(in >> y);
  std::string rest;
  in.clear();
  in >> rest;
  if (!has_x || !rest.empty() || (cmd != "orbit" && has_y))
    return error(cmd == "orbit"
                     ? ":orbit needs degrees: :orbit 15 or :orbit 15 -10"
                     : ":" + cmd + " needs a number, as in :" + cmd + (cmd == "zoom" ? " 1.5" : " 2"));
  if (cmd == "zoom" && !(x > 0)) return error(":zoom needs a positive factor");
  const std::optional<CameraAdjustment> before = step_;
  if (!step_) {
    // Pivot: the middle of what is drawn in the current frame, fixed from now on.
    std::string message;
    const std::optional<View> v = view(message);
    if (!v) return error(message);
    Extent e;
    for (const SceneObject& o : v->scene.scene.objects) e.add(*o.solid);
    CameraAdjustment a;
    if (!e.empty()) a.pivot = e.middle();
    step_ = a;
    stepped_name_ = v->camera + "_view";
  }
  if (cmd == "orbit") {
    step_->theta_deg += x;
    step_->phi_deg += has_y ? y : 0;
  } else if (cmd == "zoom") {
    step_->zoom *= x;
  } else {
    step_->dolly += x;
  }
  const ReplReply shown = show();
  if (shown.kind == ReplReply::Kind::Error) step_ = before;
  return shown;
}

std::vector<std::string> ReplSession::completions(const std::string& line, const std::string& word) const {
  std::vector<std::string> out;
  auto offer = [&](const std::string& candidate) {
    if (candidate.rfind(word, 0) == 0 && std::find(out.begin(), out.end(), candidate) == out.end())
      out.push_back(candidate);
  };
  const std::string start = trim(line);
  if (!start.empty() && start[0] == ':') {
    if (start.find(' ') != std::string::npos) return out;  // a file name: libedit completes it
    for (const Command& c : kCommands) offer(std::string(":") + c.name);
    return out;
  }
  for (const std::string& k : kKeywords) offer(k);
  for (const std::string& b : builtins().names()) offer(b);
  for (const Chunk& c : chunks_)
    for (const std::string& n : c.names) offer(n);
  std::sort(out.begin(), out.end());
  return out;
}

std::string repl_help_text() {
  std::string out =
      "Type statements as in a script (solid, let, def, draw, camera, ...); an expression alone shows its "
      "value.\nA definition of a name the session has replaces it. Commands (any unambiguous prefix):\n";
  for (const Command& c : kCommands) {
    char line[160];
    std::snprintf(line, sizeof line, "  %-16s %s\n", c.usage, c.help);
    out += line;
  }
  return out;
}

}  // namespace hlr::runtime
