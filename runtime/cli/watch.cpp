// hlrscript watch FILE: renders, then renders again whenever the script, a file it includes or a mesh
// it imports changes, until interrupted. Errors are reported and the watch goes on, so an editor and a
// PDF or SVG viewer side by side make a live preview (as OpenSCAD's automatic reload does).
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <ostream>
#include <system_error>
#include <thread>

#include "runtime/cli/cli.hpp"
#include "runtime/pipeline/script_run.hpp"

namespace hlr::runtime {

namespace {

namespace fs = std::filesystem;
using Stamp = std::map<fs::path, std::pair<fs::file_time_type, std::uintmax_t>>;

Stamp stamp_of(const std::vector<fs::path>& files) {
  Stamp s;
  for (const fs::path& f : files) {
    std::error_code ec;
    const auto time = fs::last_write_time(f, ec);
    const auto size = ec ? 0 : fs::file_size(f, ec);
    s[f] = {ec ? fs::file_time_type{} : time, ec ? 0 : size};
  }
  return s;
}

// One render, as `hlrscript FILE` does it; returns the files to watch (at least the script).
std::vector<fs::path> render_once(const CliOptions& o, std::ostream& out, std::ostream& err) {
  std::vector<fs::path> inputs;
  run_script(o, out, err, &inputs);
  std::vector<fs::path> watched = {fs::absolute(o.script).lexically_normal()};
  for (const fs::path& p : inputs)
    if (std::find(watched.begin(), watched.end(), p) == watched.end()) watched.push_back(p);
  return watched;
}

}  // namespace

int run_watch(const CliOptions& o, std::ostream& out, std::ostream& err) {
  constexpr auto kPoll = std::chrono::milliseconds(100);
  constexpr auto kSettle = std::chrono::milliseconds(150);  // an editor's save may take several writes
  std::vector<fs::path> watched = render_once(o, out, err);
  Stamp seen = stamp_of(watched);
  out << "watching " << watched.size() << (watched.size() == 1 ? " file" : " files") << "; Ctrl-C stops\n"
      << std::flush;
  err << std::flush;
  for (;;) {
    std::this_thread::sleep_for(kPoll);
    if (stamp_of(watched) == seen) continue;
    // Changed: wait until it stays the same for a moment, then render.
    Stamp now = stamp_of(watched);
    for (;;) {
      std::this_thread::sleep_for(kSettle);
      Stamp later = stamp_of(watched);
      if (later == now) break;
      now = std::move(later);
    }
    out << "changed: rendering again\n" << std::flush;
    watched = render_once(o, out, err);
    seen = stamp_of(watched);
    out << std::flush;
    err << std::flush;
  }
}

}  // namespace hlr::runtime
