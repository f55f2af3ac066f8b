// hlrscript command line. Until the scripting language lands, the command renders its built-in demo.
// Exit codes: 0 success, 64 usage error, 70 internal error, 73 cannot write output.
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "core/device/atomic_file.hpp"
#include "runtime/demo_scene.hpp"

namespace {

constexpr const char* kUsage =
    "usage: hlrscript --demo [-o OUT.pdf] [--frames N] [--hidden dashed|off]\n"
    "       hlrscript --help | --version\n"
    "\n"
    "Renders the built-in demo: Desens' aircraft carrier (1969) seen from above, then its landing\n"
    "approach in N frames (default 12), as an exact hidden-line drawing, one PDF page per frame.\n"
    "\n"
    "examples:\n"
    "  hlrscript --demo                      # writes carrier.pdf\n"
    "  hlrscript --demo -o approach.pdf --frames 48 --hidden dashed\n"
    "\n"
    "exit codes: 0 ok, 64 usage error, 70 internal error, 73 output could not be written\n";

int usage_error(const std::string& message) {
  std::fprintf(stderr, "hlrscript: error: %s\n%s", message.c_str(), kUsage);
  return 64;
}

}  // namespace

int main(int argc, char** argv) {
  bool demo = false;
  std::string out = "carrier.pdf";
  int frames = 12;
  hlr::HlrOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&](const char* what) -> const char* {
      if (i + 1 >= argc) return nullptr;
      (void)what;
      return argv[++i];
    };
    if (arg == "--help" || arg == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (arg == "--version") {
      std::puts("hlrscript 0.1.0");
      return 0;
    } else if (arg == "--demo") {
      demo = true;
    } else if (arg == "-o") {
      const char* v = value("-o");
      if (!v) return usage_error("-o needs a file name, e.g. -o carrier.pdf");
      out = v;
    } else if (arg == "--frames") {
      const char* v = value("--frames");
      char* end = nullptr;
      const long n = v ? std::strtol(v, &end, 10) : 0;
      if (!v || *end != '\0' || n < 1 || n > 10000)
        return usage_error("--frames needs a whole number from 1 to 10000");
      frames = static_cast<int>(n);
    } else if (arg == "--hidden") {
      const char* v = value("--hidden");
      if (!v || (std::strcmp(v, "dashed") != 0 && std::strcmp(v, "off") != 0))
        return usage_error("--hidden takes 'dashed' or 'off'");
      options.include_hidden = std::strcmp(v, "dashed") == 0;
    } else if (!arg.empty() && arg[0] != '-') {
      return usage_error("'" + arg + "': scripts are not read by this build yet; run 'hlrscript --demo'");
    } else {
      return usage_error("unknown option '" + arg + "'");
    }
  }
  if (!demo) return usage_error("nothing to do");
  if (out.size() < 4 || out.substr(out.size() - 4) != ".pdf")
    return usage_error("'" + out + "': this build writes PDF only; name the output *.pdf");
  try {
    hlr::DemoStats stats;
    const auto pages = hlr::render_carrier_demo(frames, options, stats);
    hlr::PdfOptions pdf;
    pdf.title = "hlrscript demo: Desens' carrier";
    hlr::write_pdf(out, pages, pdf);
    std::printf("wrote %s: %zu pages, %zu segments, hidden-line time %.1f ms (%.2f ms per frame)\n", out.c_str(),
                stats.frames, stats.segments, stats.seconds * 1e3, stats.seconds * 1e3 / stats.frames);
    return 0;
  } catch (const hlr::DeviceError& e) {
    std::fprintf(stderr, "hlrscript: error: %s\n", e.what());
    return 73;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hlrscript: internal error: %s\n", e.what());
    return 70;
  }
}
