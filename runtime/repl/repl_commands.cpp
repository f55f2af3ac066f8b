// The REPL's `:` commands, :help and Tab completion (the statements are runtime/repl/repl_session.cpp's).
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <sstream>

#include "lang/parser.hpp"
#include "runtime/base/did_you_mean.hpp"
#include "runtime/builtins/builtins.hpp"
#include "runtime/builtins/help_text.hpp"
#include "runtime/repl/repl_detail.hpp"
#include "runtime/repl/repl_session.hpp"

namespace hlr::runtime {

using repl::done;
using repl::error;
using repl::Extent;
using repl::trim;

namespace {

const std::vector<std::string> kKeywords = {
    "solid",  "let",    "def",   "for",  "if",      "else",    "draw", "camera", "animate",
    "output", "paper",  "style", "pen",  "plotter", "include", "at",   "then",   "in",
    "return", "vertex", "face",  "hole", "line",    "label",   "size", "page", "view", "dimension"};

struct Command {
  const char* name;
  const char* usage;
  const char* help;
};
const Command kCommands[] = {
    {"help", ":help [TOPIC]", "this list; a built-in, statement or command with TOPIC (:help box)"},
    {"load", ":load FILE", "replace the session by a script (then :reload reads it again)"},
    {"reload", ":reload", "read the loaded script again"},
    {"show", ":show", "draw the current frame in the terminal"},
    {"render", ":render [FILE]",
     "write the session's frames to FILE (.pdf .svg .png .hpgl .gcode .steps .json .jsonl .dxf .off .obj .stl)"},
    {"camera", ":camera [NAME]", "draw with camera NAME (no name: the last declared)"},
    {"orbit", ":orbit DTHETA [DPHI]",
     "step the camera round the scene (degrees; Albers' theta and phi keys)"},
    {"zoom", ":zoom F", "magnify the picture F times"},
    {"dolly", ":dolly D", "move the eye D scene units forward along the view"},
    {"frame", ":frame N", "look at frame N of the animation"},
    {"frames", ":frames", "how many frames the animation has, at what rate, and the one looked at"},
    {"hidden", ":hidden on|off", "draw hidden lines dashed, or not (off ends :levels too)"},
    {"levels", ":levels N",
     "draw hidden lines by occlusion level: those behind 1..N surfaces (N from 1 to 16), a layer each"},
    {"stats", ":stats", "faces, edges, visible pieces, pen plan, render time of the current frame"},
    {"scene", ":scene", "what is drawn, with sizes, and the cameras"},
    {"undo", ":undo",
     "take back the last change: an input, :load, :orbit, :zoom, :dolly, :camera, :hidden, :levels, :frame"},
    {"save", ":save FILE", "write the session as a script that renders the same drawing"},
    {"quit", ":quit", "leave (Ctrl-D too)"},
};

}  // namespace

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
  if (cmd == "help") return help(arg);
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
    auto [what, before] = std::move(undo_.back());
    undo_.pop_back();
    restore(std::move(before));
    return done("undone: " + what + "\n");
  }
  if (cmd == "orbit" || cmd == "zoom" || cmd == "dolly") return step_camera(cmd, arg);
  if (cmd == "hidden") {
    if (arg != "on" && arg != "off") return error(":hidden needs on or off");
    State before = state();
    hidden_ = arg == "on" ? HiddenStyle::dashed() : HiddenStyle::off();
    remember(":hidden " + arg, std::move(before));
    return done("hidden lines " + hidden_->words() + "\n");
  }
  if (cmd == "levels") {
    char* end = nullptr;
    const long n = std::strtol(arg.c_str(), &end, 10);
    if (arg.empty() || *end != '\0' || !valid_level_count(n))
      return error(":levels needs a whole number from 1 to " + std::to_string(kMaxOcclusionLevel) +
                   ", as in :levels 3");
    State before = state();
    hidden_ = HiddenStyle::counted(static_cast<int>(n));
    remember(":levels " + arg, std::move(before));
    return done("hidden lines by occlusion level, levels 1 to " + std::to_string(n) + "\n");
  }
  if (cmd == "camera") {
    const std::string dropped =
        step_ ? "; the :orbit, :zoom and :dolly steps are dropped (:undo brings them back)" : "";
    State before = state();
    if (arg.empty()) {
      if (!camera_ && !step_) return done("drawing with the last camera declared, as before\n");
      camera_.reset();
      step_.reset();
      remember(":camera", std::move(before));
      return done("drawing with the last camera declared" + dropped + "\n");
    }
    camera_ = arg;
    step_.reset();  // a camera chosen anew starts where its statement puts it
    std::string message;
    if (!view(message)) {
      restore(std::move(before));
      return error(message);
    }
    remember(":camera " + arg, std::move(before));
    return done("drawing with camera " + arg + dropped + "\n");
  }
  if (cmd == "frames") return frames();
  if (cmd == "frame") {
    char* end = nullptr;
    const long n = std::strtol(arg.c_str(), &end, 10);
    if (arg.empty() || *end != '\0' || n < 0 || n > 1'000'000)
      return error(":frame needs a frame number, as in :frame 3");
    State before = state();
    frame_ = static_cast<int>(n);
    const ReplReply r = scene();
    if (r.kind == ReplReply::Kind::Error)
      restore(std::move(before));
    else if (before.frame != frame_)
      remember(":frame " + arg, std::move(before));
    return r;
  }
  return error("unknown command");
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
  State before = state();
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
    stepped_name_ = "adjusted_" + v->camera;  // a name of its own in the saved script
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
  if (shown.kind == ReplReply::Kind::Error)
    restore(std::move(before));
  else
    remember(":" + cmd + " " + arguments, std::move(before));
  return shown;
}

namespace {

// The function whose argument list the text before the cursor is inside ("lookat(eye: (1, 2, 3), "
// → "lookat"), or "".
std::string open_call(const std::string& before) {
  int depth = 0;
  for (std::size_t i = before.size(); i-- > 0;) {
    const char c = before[i];
    if (c == ')' || c == ']') ++depth;
    if ((c == '(' || c == '[') && depth-- == 0) {
      if (c == '[') return "";
      std::size_t end = i;  // "lookat (" calls lookat too
      while (end > 0 && (before[end - 1] == ' ' || before[end - 1] == '\t')) --end;
      std::size_t b = end;
      while (b > 0 && (std::isalnum(static_cast<unsigned char>(before[b - 1])) || before[b - 1] == '_')) --b;
      return before.substr(b, end - b);
    }
  }
  return "";
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

std::vector<std::string> ReplSession::parameter_names(const std::string& function) const {
  for (auto chunk = chunks_.rbegin(); chunk != chunks_.rend(); ++chunk) {
    if (std::find(chunk->names.begin(), chunk->names.end(), function) == chunk->names.end()) continue;
    const lang::ParseResult parsed = lang::parse(chunk->text, "<input>");
    if (!parsed.ok()) continue;
    for (const lang::Stmt& s : parsed.script->statements)
      if (const auto* def = std::get_if<lang::DefStmt>(&s.node); def && def->name.text == function) {
        std::vector<std::string> out;
        for (const lang::Param& p : def->params) out.push_back(p.name.text);
        return out;
      }
    return {};  // a let or a solid of that name shadows the built-in
  }
  return builtin_parameter_names(function);
}

std::vector<std::string> ReplSession::completions(const std::string& line, const std::string& word) const {
  std::vector<std::string> out;
  auto offer = [&](const std::string& candidate) {
    if (candidate.rfind(word, 0) == 0 && std::find(out.begin(), out.end(), candidate) == out.end())
      out.push_back(candidate);
  };
  const std::string before = ends_with(line, word) ? line.substr(0, line.size() - word.size()) : line;
  const std::string start = trim(line);
  if (!start.empty() && start[0] == ':') {
    if (start.rfind(":h", 0) == 0 && before.find(' ') != std::string::npos) {
      for (const std::string& t : language_help_topics()) offer(t);
      for (const Command& c : kCommands) offer(c.name);
      std::sort(out.begin(), out.end());
      return out;
    }
    if (start.find(' ') != std::string::npos) return out;  // a file name: libedit completes it
    for (const Command& c : kCommands) offer(std::string(":") + c.name);
    return out;
  }
  if (ends_with(before, "import(\"") || ends_with(before, "include \"")) return out;  // file names
  // Inside a call: its parameter names first, then anything an argument's expression may use.
  const std::string callee = open_call(before);
  if (!callee.empty())
    for (const std::string& p : parameter_names(callee)) offer(p + ":");
  const std::size_t parameters = out.size();
  if (parameters > 0 && word.empty()) return out;  // right after '(' or ',': the names to give
  for (const std::string& k : kKeywords) offer(k);
  for (const std::string& b : builtins().names()) offer(b);
  for (const Chunk& c : chunks_)
    for (const std::string& n : c.names) offer(n);
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(parameters), out.end());
  return out;
}

ReplReply ReplSession::help(const std::string& topic) const {
  if (topic.empty()) return done(repl_help_text());
  const std::string name = topic[0] == ':' ? topic.substr(1) : topic;
  std::string out;
  for (const Command& c : kCommands)
    if (name == c.name) out += std::string(c.usage) + "\n  " + c.help + "\n";
  if (topic[0] != ':')
    if (const std::optional<std::string> text = language_help(topic)) out += *text;
  if (!out.empty()) return done(out);
  std::vector<std::string> topics = language_help_topics();
  for (const Command& c : kCommands) topics.push_back(std::string(":") + c.name);
  const std::string guess = did_you_mean(topic, topics);
  return error("no help on '" + topic + "'" + (guess.empty() ? "" : "; " + guess) +
               "\nhint: :help NAME for a built-in (:help box), a statement (:help draw) or a command "
               "(:help orbit)");
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
