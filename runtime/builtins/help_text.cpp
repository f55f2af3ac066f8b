#include "runtime/builtins/help_text.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "lang/parser.hpp"
#include "runtime/base/file_access.hpp"
#include "runtime/builtins/builtins.hpp"
#include "runtime/values/format_value.hpp"

namespace hlr::runtime {

namespace {

constexpr std::size_t kShownValueLength = 60;  // a default or a constant, as help shows it

struct StatementHelp {
  const char* keyword;
  const char* form;
  const char* help;
};

// The statements' forms as lang/README.md gives them, with what each does.
const StatementHelp kStatements[] = {
    {"solid", "solid NAME [(crease: 30, planarity: 0.003, ...)] { vertex ID = EXPR  face ID ID ID ... }",
     "Declares a polyhedron by its vertices and faces (hole and line items too); draw shows it."},
    {"let", "let NAME = EXPR", "Names a value; a name is bound once per scope."},
    {"def", "def NAME(a, b = 2) = EXPR  |  def NAME(a, b = 2) { ... return EXPR }",
     "Defines a function; its body sees every name of the scopes around it."},
    {"return", "return [EXPR]", "Ends a block function with a value."},
    {"for", "for NAME in EXPR { ... }", "Runs the block for each item of a list or a range a..b."},
    {"if", "if EXPR { ... } [else { ... } | else if ...]", "Runs a block when a bool is true."},
    {"draw", "draw EXPR [at TRANSFORM] [pen N]", "Adds a solid or a group to the frame's scene."},
    {"camera", "camera NAME = EXPR", "Declares a camera; without --camera the last declared draws."},
    {"animate", "animate frames N [fps F]",
     "Makes the script a sequence: it runs once per frame with frame, t and time bound."},
    {"output", "output \"name-{frame:03}.pdf\" [paper SIZE ...] [plotter NAME]",
     "Where the drawing goes (.pdf .svg .png .hpgl .gcode .steps .json .jsonl .dxf .off .obj .stl); -o "
     "overrides it."},
    {"paper", "paper SIZE [landscape|portrait] [(margin: MM, scale: MM_PER_UNIT, fit: F, title: TEXT)]",
     "The page: A4, A3, letter, ... or custom (width: W, height: H)."},
    {"style", "style hidden dashed|off|levels N [pen P]",
     "Draws hidden lines dashed, or leaves them out; levels N draws those behind 1..N surfaces, each level "
     "a layer of its own (in pen P + level - 1 with a pen)."},
    {"include", "include \"file.hls\"  |  include \"std/NAME.hls\"",
     "Runs another script in place, once; std/ names the library modules."},
    {"pen", "pen N (colour: \"red\", width: 0.35)", "Sets a pen's colour and width for every device."},
    {"plotter", "plotter NAME { KEY: EXPR ... }", "Describes a pen plotter for HPGL or G-code output."},
    {"label", "label TEXT at POINT | at page (X, Y) [size: MM] [pen N]",
     "Writes single-stroke text from a world point (hidden by the solids in front) or a page point in mm."},
    {"view", "view NAME = CAMERA at page (X, Y) [scale: MM_PER_UNIT] [label: TEXT] [hidden: BOOL]",
     "Places a camera's drawing on the sheet, its target at page (X, Y) mm; a script with views draws them "
     "all on each page, each with its own hidden lines, labelled, with a title block."},
    {"views",
     "views of PART [projection: \"third\"|\"first\"] [iso: BOOL] [scale: S] [gap: MM] [hidden: BOOL]",
     "Declares the part's standard views — front, top, right (left in first angle) and iso — laid out and "
     "lined up on the sheet in third- or first-angle projection at one scale fitted to it."},
    {"dimension",
     "dimension [angle at V] from P to Q [in VIEW] [offset: MM] [direction: D] [radius: MM] [extend: LEGS] "
     "[text: T] [precision: N] [unit: U] [pen: N]",
     "Draws the distance between two world points (or with 'angle at V', the angle P V Q) in a view of the "
     "sheet: extension lines, a dimension line (or an arc) with arrowheads and the value in single-stroke "
     "letters, hidden by nothing."},
};

const BuiltinFunction* builtin_function(const std::string& name) {
  const Value* v = builtins().find(name);
  if (!v || !v->is(ValueKind::Function)) return nullptr;
  return std::get_if<BuiltinFunction>(&v->as_function()->body);
}

// "eye (a vector)", "fov = 40 (a number)", "aspect (a number, optional)".
std::string param_text(const Param& p) {
  std::string s(p.name);
  if (!p.fallback.is_none()) s += " = " + display(p.fallback, kShownValueLength);
  s += " (" + (p.kinds == kAnyKind ? std::string("any value") : describe_kinds(p.kinds));
  if (!p.required && p.fallback.is_none()) s += ", optional";
  return s + ")";
}

std::string builtin_help(const std::string& name, const BuiltinFunction& f) {
  std::string out = f.signature + "\n  " + f.summary + "\n";
  for (std::size_t i = 0; i < f.forms.size(); ++i) {
    if (f.forms[i]->empty()) continue;
    out += f.forms.size() > 1 ? "  form " + std::to_string(i + 1) + ":" : std::string("  parameters:");
    std::string sep = " ";
    for (const Param& p : *f.forms[i]) {
      out += sep + param_text(p);
      sep = ", ";
    }
    out += "\n";
  }
  if (f.forms.empty()) out += "  any number of arguments: " + name + "(1, 2, 3) or " + name + "([1, 2, 3])\n";
  return out;
}

// ---- the library modules' functions ------------------------------------------------------------------

struct ModuleFunction {
  std::string module;     // "std/gears.hls"
  std::string signature;  // "gear(teeth, m, thickness, bore = 0, key = true)"
  std::string doc;        // the comment lines right above the def, without '#'
};

// Every top-level def of the library modules, read from their files (in stdlib_module_directory()).
std::vector<ModuleFunction> module_functions() {
  std::vector<ModuleFunction> out;
  for (const std::filesystem::path& file : library_module_files()) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    const std::string module = "std/" + file.filename().string();
    const lang::ParseResult parsed = lang::parse(text.str(), module);
    if (!parsed.ok()) continue;
    const std::string& t = parsed.source->text();
    for (const lang::Stmt& stmt : parsed.script->statements) {
      const auto* def = std::get_if<lang::DefStmt>(&stmt.node);
      if (!def) continue;
      // The signature as written: from the name to its parameter list's ')'.
      const std::size_t name_at = def->name.span.begin;
      std::size_t close = t.find('(', name_at);
      for (int depth = 0; close < t.size(); ++close) {
        depth += t[close] == '(' ? 1 : t[close] == ')' ? -1 : 0;
        if (depth == 0) break;
      }
      ModuleFunction f{module, t.substr(name_at, close + 1 - name_at), ""};
      // The comment block right above the def's line.
      std::size_t line_start = t.rfind('\n', stmt.span.begin == 0 ? 0 : stmt.span.begin - 1);
      std::vector<std::string> lines;
      while (line_start != std::string::npos && line_start > 0) {
        const std::size_t prev = t.rfind('\n', line_start - 1);
        const std::size_t begin = prev == std::string::npos ? 0 : prev + 1;
        std::string line = t.substr(begin, line_start - begin);
        line.erase(0, line.find_first_not_of(" \t"));
        if (line.empty() || line[0] != '#') break;
        lines.push_back(line.substr(line.size() > 1 && line[1] == ' ' ? 2 : 1));
        if (prev == std::string::npos) break;
        line_start = prev;
      }
      std::reverse(lines.begin(), lines.end());
      for (const std::string& l : lines) f.doc += "  " + l + "\n";
      out.push_back(std::move(f));
    }
  }
  return out;
}

std::string function_name(const ModuleFunction& f) { return f.signature.substr(0, f.signature.find('(')); }

}  // namespace

std::optional<std::string> language_help(const std::string& topic) {
  for (const StatementHelp& s : kStatements)
    if (topic == s.keyword) return std::string(s.form) + "\n  " + s.help + "\n";
  const Value* v = builtins().find(topic);
  if (v && !v->is(ValueKind::Function))
    return topic + " = " + display(*v, kShownValueLength) + " (a built-in constant)\n";
  if (const BuiltinFunction* f = builtin_function(topic)) return builtin_help(topic, *f);
  for (const ModuleFunction& f : module_functions())
    if (function_name(f) == topic)
      return f.signature + "   (library module " + f.module + ": include \"" + f.module + "\" first)\n" +
             f.doc;
  return std::nullopt;
}

std::vector<std::string> language_help_topics() {
  std::vector<std::string> out = builtins().names();
  for (const StatementHelp& s : kStatements) out.push_back(s.keyword);
  for (const ModuleFunction& f : module_functions()) out.push_back(function_name(f));
  std::sort(out.begin(), out.end());
  return out;
}

std::string builtin_reference() {
  std::string out =
      "# hlrscript built-ins\n\n"
      "Generated from the built-ins' registration tables by `hlrscript help reference` (the REPL's\n"
      "`:help NAME` prints the same entries); a test checks that this file is current. Angles are in\n"
      "degrees. A parameter with `= value` may be left out; `optional` ones have no default.\n\n"
      "## Statements\n\n";
  for (const StatementHelp& s : kStatements) out += "- `" + std::string(s.form) + "` — " + s.help + "\n";
  out += "\n## Functions and constants\n\n";
  for (const std::string& name : builtins().names()) {
    const std::optional<std::string> help = language_help(name);
    // The first line is the signature; the rest, indented by two, become the entry's text.
    const std::size_t newline = help->find('\n');
    out += "### " + name + "\n\n`" + help->substr(0, newline) + "`\n\n";
    // The summary as a paragraph, the parameter lists under it as a list.
    const std::string rest = help->substr(newline + 1);
    bool summary = true;
    for (std::size_t at = 0; at < rest.size();) {
      const std::size_t end = rest.find('\n', at);
      std::string line = rest.substr(at, end - at);
      line.erase(0, line.find_first_not_of(' '));
      out += (summary ? "" : "- ") + line + (summary ? "\n\n" : "\n");
      summary = false;
      at = end + 1;
    }
    if (!summary) out += "\n";
  }
  return out;
}

std::vector<std::string> builtin_parameter_names(const std::string& function) {
  std::vector<std::string> out;
  if (const BuiltinFunction* f = builtin_function(function))
    for (const ParamList* form : f->forms)
      for (const Param& p : *form)
        if (std::find(out.begin(), out.end(), p.name) == out.end()) out.emplace_back(p.name);
  return out;
}

}  // namespace hlr::runtime
