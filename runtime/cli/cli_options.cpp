// The command line, parsed with Boost.Program_options into CliOptions; every mistake is a usage error
// (exit 64) that says what was expected.
#include <algorithm>
#include <boost/program_options.hpp>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <ostream>
#include <set>
#include <sstream>

#include "core/device/page/hidden_style.hpp"
#include "core/device/page/page_layout.hpp"
#include "core/format_number.hpp"
#include "core/limits.hpp"
#include "runtime/base/limits.hpp"
#include "runtime/cli/cli.hpp"
#include "runtime/pipeline/output_plan.hpp"

namespace hlr::runtime {

namespace po = boost::program_options;

namespace {

po::options_description visible_options() {
  po::options_description o("options");
  o.add_options()                                                //
      ("output,o", po::value<std::string>()->value_name("OUT"),  //
       "output file: .pdf (one page per frame), .svg, .png, .hpgl, .gcode (one frame per file), .json or "
       ".jsonl (a frame a line); {frame:04} in the name writes one file per frame")  //
      ("camera", po::value<std::string>()->value_name("NAME"),
       "camera to draw with (default: the last declared)")  //
      ("frames", po::value<std::string>()->value_name("LIST"),
       "render only these frames (0-based): A-B, A, A- (to the end), or a list: 0,5,10-20")  //
      ("shard", po::value<std::string>()->value_name("K/N"),
       "render the frames f with f % N == K-1 (job K of N; with --frames, of those); auto: K/N of a Slurm "
       "job array; auto/N: K from a Kubernetes indexed Job or GNU parallel")  //
      ("jobs,j", po::value<std::string>()->value_name("N"),
       "use N threads for frames and the hidden lines inside them (default 0: one per core)")  //
      ("hidden", po::value<std::string>()->value_name("off|dashed"),
       "hidden lines: off, or dashed (overrides the script)")  //
      ("levels", po::value<std::string>()->value_name("N"),
       "hidden lines by occlusion level: the pieces behind 1..N surfaces (N from 1 to 16), each level a "
       "layer and dash of its own (overrides the script's style hidden, keeps its pen)")  //
      ("limit", po::value<std::vector<std::string>>()->value_name("NAME=N")->composing(),
       "raise (or lower) a limit of each frame, repeatable: steps (evaluation steps, 10000000), faces "
       "(built and drawn, 10000000), vertices (drawn, 30000000), segments (visible pieces, 20000000), memory "
       "(MB estimated for the solids made, 16384), calls (nesting, 256), list (items, 10000000), string "
       "(bytes, 10000000)")  //
      ("frame-timeout", po::value<std::string>()->value_name("SECONDS"),
       "stop a frame that takes longer (evaluation, hidden lines and pen plan) with an error; default "
       "none")                                                                                    //
      ("keep-going", "when a frame fails, render the other frames anyway (the run still fails)")  //
      ("stats", "print per-frame statistics (hidden-line and pen plan) to stderr")                //
      ("paper", po::value<std::string>()->value_name("SIZE"),
       "paper: A0-A6, Letter, Legal, Tabloid or WxH in mm (e.g. 420x297); overrides the script")      //
      ("landscape", "landscape paper (the default)")                                                  //
      ("portrait", "portrait paper")                                                                  //
      ("margin", po::value<std::string>()->value_name("MM"), "margin on every side (default 12 mm)")  //
      ("scale", po::value<std::string>()->value_name("MM"),
       "1 picture unit = MM millimetres, centred, instead of the camera's field of view")  //
      ("fit", po::value<std::string>()->value_name("camera|drawing"),
       "what fills the page: the camera's view (default; the same scale in every frame) or what is drawn")  //
      ("dash", po::value<std::string>()->value_name("DASH,GAP"),
       "hidden lines on HPGL, G-code and .steps: pen-down dashes of DASH mm with GAP mm between (default "
       "2,1.5)")                                                                          //
      ("dpi", po::value<std::string>()->value_name("N"), "PNG resolution (default 150)")  //
      ("line-width", po::value<std::string>()->value_name("MM"),
       "pen width on PDF/SVG/PNG (default 0.25)")  //
      ("plotter", po::value<std::string>()->value_name("NAME"),
       "HPGL plotter profile: generic (default), hp7475a, hp7440a, hp7550, roland-dxy; G-code (.gcode): "
       "grbl-servo (default), grbl-z; or one the script declares")  //
      ("step", po::value<std::string>()->value_name("MM"),
       "step of the incremental plotter tape (.steps; default 0.1 mm)")  //
      ("plain", "no frame border or caption")                            //
      ("svg", po::value<std::string>()->value_name("plotter|document"),
       "SVG for a pen plotter (AxiDraw, vpype, Inkscape: a layer per pen, a path per planned stroke, "
       "nothing else) or a document (cairo: border, caption); default document, plotter when a plotter is "
       "named")  //
      ("text", po::value<std::string>()->value_name("stroke|outline"),
       "the caption in single-stroke letters planned with the drawing (the default on HPGL, G-code and "
       "plotter SVG) or as a font's outlines (the default on PDF, SVG, PNG and JSON)")  //
      ("clip",
       "cut strokes at the plotter's reach (HPGL) or the page (G-code, plotter SVG) instead of failing")  //
      ("hpgl-moves", po::value<std::string>()->value_name("relative|absolute"),
       "HPGL moves (default: the profile's)")  //
      ("json", po::value<std::string>()->value_name("LIST"),
       "what each JSON frame holds besides its number and time: all (the default) or a comma-separated list "
       "of camera, layout, segments, strokes, stats")  //
      ("pen-order", po::value<std::string>()->value_name("none|greedy|optimized"),
       "pen planning: file order, greedy nearest-end, or optimized (default)")  //
      ("plan-effort", po::value<std::string>()->value_name("N"),
       "improvement work of the optimized pen plan per stroke (default 500; 0: the circuit order): counted, "
       "never timed, so reruns give the same bytes")  //
      ("allow-path", po::value<std::vector<std::string>>()->value_name("DIR")->composing(),
       "let the script include and import files below DIR too (repeatable); by default it reads only below "
       "its own folder and the library modules")  //
      ("out-dir", po::value<std::string>()->value_name("DIR"),
       "where the outputs the script names go (default: the working directory); -o may name any path")      //
      ("demo", "render the built-in demo (Desens' aircraft carrier); --frames N sets its approach frames")  //
      ("quiet,q", "no progress line on a terminal")                                                         //
      ("verbose", "also print notes on what the script's options accept (warped faces, crossing holes)")    //
      ("repl", "start the REPL (also: hlrscript repl [FILE], or hlrscript alone in a terminal)")            //
      ("list-cameras", "print the cameras FILE declares, one a line (for shell completion), and exit")      //
      ("list-plotters", "print the built-in plotter profiles, one a line, and exit")                        //
      ("help,h", "show this help")                                                                          //
      ("version", "show the version");
  return o;
}

constexpr const char* kExamples =
    "examples:\n"
    "  hlrscript scene.hls                               # every frame to scene.pdf, one page each\n"
    "  hlrscript scene.hls -o top.pdf --camera top       # another camera, another file\n"
    "  hlrscript scene.hls -o lines.json                 # the visible segments as JSON\n"
    "  hlrscript scene.hls -o scene.svg --paper A3       # SVG on A3 landscape\n"
    "  hlrscript scene.hls -o scene.png --dpi 300        # a quick raster\n"
    "  hlrscript scene.hls -o scene.svg --svg plotter    # layers per pen for AxiDraw, vpype, Inkscape\n"
    "  hlrscript scene.hls -o scene.hpgl --plotter hp7475a --paper A4   # for an HP 7475A\n"
    "  hlrscript landing.hls -o 'f-{frame:03}.hpgl'      # one plotter file per frame\n"
    "  hlrscript scene.hls -o scene.gcode --plotter grbl-z   # G-code for a GRBL machine, pen on Z\n"
    "  hlrscript landing.hls -o 'f-{frame:04}.pdf' --frames 0-99 --jobs 2\n"
    "  hlrscript landing.hls -o 'f-{frame:04}.pdf' --shard 3/8    # job 3 of 8: frames 2, 10, 18, ...\n"
    "  sbatch --array=1-8 --wrap \"hlrscript landing.hls -o 'f-{frame:04}.pdf' --shard auto\"  # Slurm\n"
    "  hlrscript check scene.hls                         # evaluate every frame, write nothing\n"
    "  hlrscript --demo -o carrier.pdf                   # the built-in demo\n"
    "\n"
    "exit codes: 0 ok, 64 usage error, 65 error in the script, 66 a file cannot be read,\n"
    "            70 internal error, 73 an output cannot be written, 77 the script reached outside\n"
    "            what it may read or write (--allow-path, --out-dir), 130 stopped (Ctrl-C)\n";

std::nullopt_t usage_error(std::ostream& err, const std::string& message) {
  err << "hlrscript: error: " << message << "\n"
      << "usage: hlrscript FILE.hls [-o OUT] [--camera NAME] [--frames A-B] [--shard K/N] [--jobs N]\n"
      << "       (hlrscript --help for more)\n";
  return std::nullopt;
}

// A finite number in [lo, hi] from an option's text.
bool number_option(const po::variables_map& vm, const char* name, double lo, double hi,
                   std::optional<double>& out, std::string& error) {
  if (!vm.count(name)) return true;
  const std::string text = vm[name].as<std::string>();
  double v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || !(v >= lo && v <= hi)) {
    error = std::string("--") + name + " " + text + ": expected a number from " + format_for_message(lo) +
            " to " + format_for_message(hi);
    return false;
  }
  out = v;
  return true;
}

// An option taking one of two words: true for the first, false for the second.
bool either_option(const po::variables_map& vm, const char* name, const char* yes, const char* no,
                   std::optional<bool>& out, std::string& error) {
  if (!vm.count(name)) return true;
  const std::string v = vm[name].as<std::string>();
  if (v != yes && v != no) {
    error = std::string("--") + name + " takes '" + yes + "' or '" + no + "', not '" + v + "'";
    return false;
  }
  out = v == yes;
  return true;
}

// --dash DASH,GAP: two lengths in mm, each from 0.1 to 100; --dash solid: hidden strokes drawn whole.
bool parse_dash(const std::string& text, std::optional<DashPattern>& out, std::string& error) {
  if (text == "solid") {
    out.reset();
    return true;
  }
  const auto number = [](std::string_view s, double& v) {
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    return r.ec == std::errc() && r.ptr == s.data() + s.size() && v >= 0.1 && v <= 100;
  };
  const std::size_t comma = text.find(',');
  double dash = 0, gap = 0;
  if (comma == std::string::npos || !number(std::string_view(text).substr(0, comma), dash) ||
      !number(std::string_view(text).substr(comma + 1), gap)) {
    error = "--dash " + text +
            ": expected DASH,GAP in millimetres, each from 0.1 to 100 (e.g. --dash 2,1.5), or solid";
    return false;
  }
  out = {dash, gap};
  return true;
}

bool parse_device_options(const po::variables_map& vm, DeviceOptions& d, std::string& error) {
  if (vm.count("landscape") && vm.count("portrait")) {
    error = "--landscape and --portrait exclude each other";
    return false;
  }
  if (vm.count("landscape")) d.landscape = true;
  if (vm.count("portrait")) d.landscape = false;
  if (vm.count("paper")) {
    d.paper = vm["paper"].as<std::string>();
    if (!parse_paper(*d.paper, d.landscape.value_or(true))) {
      std::string names;
      for (const std::string_view n : paper_names()) names += (names.empty() ? "" : ", ") + std::string(n);
      error = "--paper " + *d.paper + ": unknown paper size; use " + names + " or WxH in mm (e.g. 420x297)";
      return false;
    }
  }
  std::optional<double> dpi;
  if (!number_option(vm, "margin", 0, 1000, d.margin_mm, error) ||
      !number_option(vm, "scale", kMinMmPerUnit, kMaxMmPerUnit, d.mm_per_unit, error) ||
      !number_option(vm, "dpi", 10, 2400, dpi, error) ||
      !number_option(vm, "line-width", 0.01, kMaxPenWidthMm, d.line_width_mm, error))
    return false;
  if (dpi) d.dpi = *dpi;
  std::optional<double> step;
  if (!number_option(vm, "step", kMinPlotterStepMm, kMaxPlotterStepMm, step, error)) return false;
  if (step) d.step_mm = *step;
  std::optional<double> effort;
  if (!number_option(vm, "plan-effort", 0, static_cast<double>(kMaxPlanEffort), effort, error)) return false;
  if (effort) {
    if (*effort != std::floor(*effort)) {
      error = "--plan-effort " + vm["plan-effort"].as<std::string>() + ": expected a whole number";
      return false;
    }
    d.plan_effort = static_cast<std::size_t>(*effort);
  }
  if (vm.count("plotter")) d.plotter = vm["plotter"].as<std::string>();
  d.clip = vm.count("clip") > 0;
  d.decorations = vm.count("plain") == 0;
  if (!either_option(vm, "text", "stroke", "outline", d.text_strokes, error) ||
      !either_option(vm, "svg", "plotter", "document", d.plotter_svg, error) ||
      !either_option(vm, "hpgl-moves", "relative", "absolute", d.relative, error))
    return false;
  if (vm.count("dash") && !parse_dash(vm["dash"].as<std::string>(), d.dash, error)) return false;
  std::optional<bool> fit_camera;
  if (!either_option(vm, "fit", "camera", "drawing", fit_camera, error)) return false;
  if (fit_camera) d.fit = *fit_camera ? PageFit::Camera : PageFit::Drawing;
  if (vm.count("json")) {
    const std::string v = vm["json"].as<std::string>();
    const std::optional<JsonParts> parts = parse_json_parts(v);
    if (!parts) {
      error =
          "--json takes all or a comma-separated list of camera, layout, segments, strokes, stats, not '" +
          v + "'";
      return false;
    }
    d.json_parts = *parts;
  }
  if (vm.count("pen-order")) {
    const std::string v = vm["pen-order"].as<std::string>();
    if (v == "none")
      d.pen_order = PenOrder::None;
    else if (v == "greedy")
      d.pen_order = PenOrder::Greedy;
    else if (v == "optimized" || v == "optimised")
      d.pen_order = PenOrder::Optimized;
    else {
      error = "--pen-order takes none, greedy or optimized, not '" + v + "'";
      return false;
    }
  }
  return true;
}

// --limit NAME=N (each name once; N a whole number from 1) and --frame-timeout SECONDS.
bool parse_limits(const po::variables_map& vm, Limits& limits, std::string& error) {
  std::set<std::string> seen;
  if (vm.count("limit"))
    for (const std::string& text : vm["limit"].as<std::vector<std::string>>()) {
      const std::size_t eq = text.find('=');
      const std::string name = text.substr(0, eq);
      std::string names;
      for (const char* n : kLimitNames) names += (names.empty() ? "" : ", ") + std::string(n);
      if (eq == std::string::npos ||
          std::find(std::begin(kLimitNames), std::end(kLimitNames), name) == std::end(kLimitNames)) {
        error = "--limit " + text + ": expected NAME=N with NAME one of " + names;
        return false;
      }
      if (!seen.insert(name).second) {
        error = "--limit " + name + " is given twice";
        return false;
      }
      const std::string value = text.substr(eq + 1);
      std::uint64_t n = 0;
      const auto r = std::from_chars(value.data(), value.data() + value.size(), n);
      constexpr std::uint64_t kCeiling = std::uint64_t{1} << 40;
      // Calls nest on the evaluator's own stack, sized for kMaxEvalDepth levels.
      const std::uint64_t most = name == "calls" ? kMaxEvalDepth / 4 : kCeiling;
      if (r.ec != std::errc() || r.ptr != value.data() + value.size() || n < 1 || n > most) {
        error = "--limit " + text + ": expected a whole number from 1 to " + std::to_string(most);
        return false;
      }
      if (name == "steps") limits.steps = n;
      if (name == "faces") limits.faces = n;
      if (name == "vertices") limits.vertices = n;
      if (name == "segments") limits.segments = n;
      if (name == "memory") limits.memory_mb = n;
      if (name == "calls") limits.calls = n;
      if (name == "list") limits.list = n;
      if (name == "string") limits.string = n;
    }
  std::optional<double> timeout;
  if (!number_option(vm, "frame-timeout", 0.001, 1e6, timeout, error)) return false;
  if (timeout) limits.frame_timeout_s = *timeout;
  return true;
}

// A folder named by --allow-path or --out-dir must exist: a typo would otherwise allow nothing (or send
// the outputs nowhere) without a word.
bool parse_access_options(const po::variables_map& vm, AccessOptions& a, std::string& error) {
  const auto folder = [&](const std::string& option, const std::string& dir) {
    std::error_code ec;
    if (dir.empty() || !std::filesystem::is_directory(dir, ec)) {
      error = "--" + option + " " + dir + ": no such folder";
      return false;
    }
    return true;
  };
  if (vm.count("allow-path"))
    for (const std::string& dir : vm["allow-path"].as<std::vector<std::string>>()) {
      if (!folder("allow-path", dir)) return false;
      a.allow_paths.emplace_back(dir);
    }
  if (vm.count("out-dir")) {
    const std::string dir = vm["out-dir"].as<std::string>();
    if (!folder("out-dir", dir)) return false;
    a.out_dir = dir;
  }
  return true;
}

}  // namespace

std::string usage_text() {
  std::ostringstream s;
  s << "usage: hlrscript FILE.hls [-o OUT.pdf|.svg|.png|.hpgl|.gcode|.json|.jsonl] [--camera NAME] [--frames "
       "A-B]\n"
       "                          [--shard K/N] [--jobs N] [--hidden off|dashed | --levels N] [--stats]\n"
       "                          [--paper SIZE] [--portrait] [--margin MM] [--scale MM] [--dpi N]\n"
       "                          [--fit camera|drawing]\n"
       "                          [--plotter NAME] [--clip] [--pen-order none|greedy|optimized]\n"
       "       hlrscript check FILE.hls [--camera NAME] [--frames A-B] [--shard K/N]\n"
       "       hlrscript watch FILE.hls [-o OUT] [options]   # render again whenever an input changes\n"
       "       hlrscript --demo [-o OUT.pdf] [--frames N] [--hidden off|dashed]\n"
       "       hlrscript [repl [FILE]]             # the REPL; with a pipe on stdin: the script it carries\n"
       "       hlrscript help [NAME|reference]     # a built-in or statement; every built-in in Markdown\n"
       "       hlrscript --help | --version\n"
       "\n"
       "Evaluates an hlrscript scene once per frame and draws each frame as an exact hidden-line drawing.\n"
       "Output: -o, else the script's 'output' statement, else FILE.pdf in the working directory.\n"
       "\n"
    << visible_options() << "\n"
    << kExamples;
  return s.str();
}

std::optional<CliOptions> parse_cli(int argc, const char* const argv[], std::ostream& err) {
  po::options_description all;
  all.add(visible_options());
  all.add_options()("args", po::value<std::vector<std::string>>(), "");
  po::positional_options_description positional;
  positional.add("args", -1);
  po::variables_map vm;
  try {
    po::store(po::command_line_parser(argc, argv).options(all).positional(positional).run(), vm);
    po::notify(vm);
  } catch (const po::error& e) {
    return usage_error(err, e.what());
  }

  CliOptions o;
  if (vm.count("help"))
    o.mode = CliOptions::Mode::Help;
  else if (vm.count("version"))
    o.mode = CliOptions::Mode::Version;
  else if (vm.count("list-plotters"))
    o.mode = CliOptions::Mode::ListPlotters;
  else if (vm.count("demo"))
    o.mode = CliOptions::Mode::Demo;
  if (o.mode == CliOptions::Mode::Help || o.mode == CliOptions::Mode::Version ||
      o.mode == CliOptions::Mode::ListPlotters)
    return o;

  std::vector<std::string> args =
      vm.count("args") ? vm["args"].as<std::vector<std::string>>() : std::vector<std::string>{};
  if (o.mode == CliOptions::Mode::Render && !args.empty() && args.front() == "help") {
    if (args.size() > 2) return usage_error(err, "help takes one topic, as in: hlrscript help box");
    o.mode = CliOptions::Mode::Help;
    if (args.size() == 2) o.help_topic = args[1];
    return o;
  }
  if (o.mode == CliOptions::Mode::Demo) {
    if (!args.empty()) return usage_error(err, "--demo takes no script ('" + args.front() + "')");
  } else {
    if (!args.empty() && (args.front() == "check" || args.front() == "watch")) {
      o.mode = args.front() == "check" ? CliOptions::Mode::Check : CliOptions::Mode::Watch;
      args.erase(args.begin());
    } else if ((!args.empty() && args.front() == "repl") || vm.count("repl")) {
      o.mode = CliOptions::Mode::Repl;
      o.repl_requested = true;
      if (!args.empty() && args.front() == "repl") args.erase(args.begin());
    } else if (args.empty()) {
      o.mode = CliOptions::Mode::Repl;  // a terminal session, or standard input as a script
    }
    if (args.empty() && o.mode == CliOptions::Mode::Check)
      return usage_error(err, "check needs a script: hlrscript check FILE.hls");
    if (args.empty() && o.mode == CliOptions::Mode::Watch)
      return usage_error(err, "watch needs a script: hlrscript watch FILE.hls [-o OUT]");
    if (args.size() > 1)
      return usage_error(err, "one script at a time (got '" + args[0] + "' and '" + args[1] + "')");
    if (!args.empty()) o.script = args.front();
    if (vm.count("list-cameras")) {
      if (o.script.empty() || o.mode != CliOptions::Mode::Render)
        return usage_error(err, "--list-cameras needs a script: hlrscript --list-cameras FILE.hls");
      o.mode = CliOptions::Mode::Check;
      o.list_cameras = true;
    }
  }

  std::string error;
  if (vm.count("output")) {
    o.output = vm["output"].as<std::string>();
    if (o.output->empty()) return usage_error(err, "-o needs a file name");
  }
  if (vm.count("camera")) o.camera = vm["camera"].as<std::string>();
  if (vm.count("frames")) {
    const std::string text = vm["frames"].as<std::string>();
    if (o.mode == CliOptions::Mode::Demo) {
      int n = 0;
      const auto r = std::from_chars(text.data(), text.data() + text.size(), n);
      if (r.ec != std::errc() || r.ptr != text.data() + text.size() || n < 1 ||
          n >= static_cast<int>(kMaxFrames))
        return usage_error(
            err, "--demo --frames needs a whole number from 1 to " + std::to_string(kMaxFrames - 1));
      o.demo_frames = n;
    } else if (!(o.frames = parse_frame_list(text, error))) {
      return usage_error(err, error);
    }
  }
  if (vm.count("shard") && !(o.shard = parse_shard(vm["shard"].as<std::string>(), error)))
    return usage_error(err, error);
  if (vm.count("jobs")) {
    const std::string text = vm["jobs"].as<std::string>();
    unsigned n = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), n);
    if (r.ec != std::errc() || r.ptr != text.data() + text.size() || n > 1024)
      return usage_error(err, "--jobs " + text + ": expected a whole number from 0 to 1024");
    o.jobs = n;
  }
  if (vm.count("hidden") && vm.count("levels"))
    return usage_error(err,
                       "--hidden and --levels exclude each other: --levels N draws the hidden lines too");
  if (vm.count("hidden")) {
    const std::string v = vm["hidden"].as<std::string>();
    if (v != "off" && v != "dashed")
      return usage_error(err, "--hidden takes 'off' or 'dashed', not '" + v + "'");
    o.hidden = v == "dashed" ? HiddenStyle::dashed() : HiddenStyle::off();
  }
  if (vm.count("levels")) {
    const std::string text = vm["levels"].as<std::string>();
    int n = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), n);
    if (r.ec != std::errc() || r.ptr != text.data() + text.size() || !valid_level_count(n))
      return usage_error(err, "--levels " + text + ": expected a whole number from 1 to " +
                                  std::to_string(kMaxOcclusionLevel) + " (the occlusion levels drawn)");
    o.hidden = HiddenStyle::counted(n);
  }
  o.stats = vm.count("stats") > 0;
  o.keep_going = vm.count("keep-going") > 0;
  o.verbose = vm.count("verbose") > 0;
  o.quiet = vm.count("quiet") > 0;
  if (!parse_device_options(vm, o.device, error)) return usage_error(err, error);
  if (!parse_access_options(vm, o.access, error)) return usage_error(err, error);
  if (!parse_limits(vm, o.limits, error)) return usage_error(err, error);
  if (o.mode == CliOptions::Mode::Check && o.output) return usage_error(err, "check writes nothing; drop -o");
  o.check = o.mode == CliOptions::Mode::Check;
  return o;
}

}  // namespace hlr::runtime
