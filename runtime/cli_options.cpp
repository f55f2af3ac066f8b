// The command line, parsed with Boost.Program_options into CliOptions; every mistake is a usage error
// (exit 64) that says what was expected.
#include <boost/program_options.hpp>
#include <charconv>
#include <ostream>
#include <sstream>

#include "runtime/cli.hpp"
#include "runtime/output_plan.hpp"

namespace hlr::runtime {

namespace po = boost::program_options;

namespace {

po::options_description visible_options() {
  po::options_description o("options");
  o.add_options()                                                //
      ("output,o", po::value<std::string>()->value_name("OUT"),  //
       "output file: .pdf (one page per frame) or .json; {frame:04} in the name writes one file per frame")  //
      ("camera", po::value<std::string>()->value_name("NAME"),
       "camera to draw with (default: the last declared)")  //
      ("frames", po::value<std::string>()->value_name("A-B"),
       "render frames A to B only (0-based, inclusive)")  //
      ("shard", po::value<std::string>()->value_name("K/N"),
       "render the frames f with f % N == K-1 (job K of N; with --frames, of those)")                       //
      ("jobs,j", po::value<std::string>()->value_name("N"), "render N frames at a time (0: one per core)")  //
      ("hidden", po::value<std::string>()->value_name("off|dashed"),
       "hidden lines: off, or dashed (overrides the script)")                                               //
      ("stats", "print per-frame statistics to stderr")                                                     //
      ("demo", "render the built-in demo (Desens' aircraft carrier); --frames N sets its approach frames")  //
      ("help,h", "show this help")                                                                          //
      ("version", "show the version");
  return o;
}

constexpr const char* kExamples =
    "examples:\n"
    "  hlrscript scene.hls                               # every frame to scene.pdf, one page each\n"
    "  hlrscript scene.hls -o top.pdf --camera top       # another camera, another file\n"
    "  hlrscript scene.hls -o lines.json                 # the visible segments as JSON\n"
    "  hlrscript landing.hls -o 'f-{frame:04}.pdf' --frames 0-99 --jobs 2\n"
    "  hlrscript landing.hls -o 'f-{frame:04}.pdf' --shard 3/8    # job 3 of 8: frames 2, 10, 18, ...\n"
    "  hlrscript check scene.hls                         # evaluate every frame, write nothing\n"
    "  hlrscript --demo -o carrier.pdf                   # the built-in demo\n"
    "\n"
    "exit codes: 0 ok, 64 usage error, 65 error in the script, 66 a file cannot be read,\n"
    "            70 internal error, 73 an output cannot be written\n";

std::nullopt_t usage_error(std::ostream& err, const std::string& message) {
  err << "hlrscript: error: " << message << "\n"
      << "usage: hlrscript FILE.hls [-o OUT] [--camera NAME] [--frames A-B] [--shard K/N] [--jobs N]\n"
      << "       (hlrscript --help for more)\n";
  return std::nullopt;
}

}  // namespace

std::string usage_text() {
  std::ostringstream s;
  s << "usage: hlrscript FILE.hls [-o OUT.pdf|OUT.json] [--camera NAME] [--frames A-B] [--shard K/N]\n"
       "                          [--jobs N] [--hidden off|dashed] [--stats]\n"
       "       hlrscript check FILE.hls [--camera NAME] [--frames A-B] [--shard K/N]\n"
       "       hlrscript --demo [-o OUT.pdf] [--frames N] [--hidden off|dashed]\n"
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
  else if (vm.count("demo"))
    o.mode = CliOptions::Mode::Demo;
  if (o.mode == CliOptions::Mode::Help || o.mode == CliOptions::Mode::Version) return o;

  std::vector<std::string> args =
      vm.count("args") ? vm["args"].as<std::vector<std::string>>() : std::vector<std::string>{};
  if (o.mode == CliOptions::Mode::Demo) {
    if (!args.empty()) return usage_error(err, "--demo takes no script ('" + args.front() + "')");
  } else {
    if (!args.empty() && args.front() == "check") {
      o.mode = CliOptions::Mode::Check;
      args.erase(args.begin());
    }
    if (args.empty())
      return usage_error(err, o.mode == CliOptions::Mode::Check
                                  ? "check needs a script: hlrscript check FILE.hls"
                                  : "no script given (the REPL is not part of this build)");
    if (args.size() > 1)
      return usage_error(err, "one script at a time (got '" + args[0] + "' and '" + args[1] + "')");
    o.script = args.front();
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
      if (r.ec != std::errc() || r.ptr != text.data() + text.size() || n < 1 || n > 10000)
        return usage_error(err, "--demo --frames needs a whole number from 1 to 10000");
      o.demo_frames = n;
    } else if (!(o.frames = parse_frame_range(text, error))) {
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
  if (vm.count("hidden")) {
    const std::string v = vm["hidden"].as<std::string>();
    if (v != "off" && v != "dashed")
      return usage_error(err, "--hidden takes 'off' or 'dashed', not '" + v + "'");
    o.hidden = v == "dashed";
  }
  o.stats = vm.count("stats") > 0;
  if (o.mode == CliOptions::Mode::Check && o.output) return usage_error(err, "check writes nothing; drop -o");
  return o;
}

}  // namespace hlr::runtime
