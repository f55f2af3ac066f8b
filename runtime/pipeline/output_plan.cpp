#include "runtime/pipeline/output_plan.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>

#include "core/device/page/atomic_file.hpp"
#include "runtime/base/eval_error.hpp"
#include "runtime/values/format_value.hpp"

namespace hlr::runtime {

namespace fs = std::filesystem;

bool has_frame_field(const std::string& pattern) { return pattern.find('{') != std::string::npos; }

std::string substitute_frame(const std::string& pattern, int frame) {
  std::string out;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '{') {
      out += pattern[i];
      continue;
    }
    const std::size_t close = pattern.find('}', i);
    const std::string field =
        pattern.substr(i + 1, close == std::string::npos ? std::string::npos : close - i - 1);
    const std::string usage = "write {frame} or {frame:04}";
    if (close == std::string::npos) throw RunError("-o " + pattern + ": '{' is not closed", usage, 64);
    const std::size_t colon = field.find(':');
    if (field.substr(0, colon) != "frame")
      throw RunError(
          "-o " + pattern + ": only {frame} can be replaced in an output name, not {" + field + "}", usage,
          64);
    try {
      out += colon == std::string::npos ? format_number(frame)
                                        : format_value(Value::number(frame), field.substr(colon + 1), 4096);
    } catch (const FormatError& e) {
      throw RunError("-o " + pattern + ": " + e.what(), usage, 64);
    }
    i = close;
  }
  return out;
}

namespace {

fs::path canonical_or_absolute(const fs::path& p) {
  std::error_code ec;
  fs::path c = fs::weakly_canonical(fs::absolute(p, ec), ec);
  return ec ? fs::absolute(p).lexically_normal() : c;
}

// Why `path` cannot be an output, or "".
std::string output_problem(const fs::path& path, const Program& program) {
  if (!device_kind_for(path))
    return "'" + path.string() + "': unknown output type '" + path.extension().string() +
           "'; supported: " + supported_extensions();
  const fs::path target = canonical_or_absolute(path);
  for (const fs::path& input : program.sources().paths())
    if (target == input)
      return "'" + path.string() + "' is an input file of this run; refusing to overwrite it";
  return "";
}

}  // namespace

OutputTarget target_for_frame(const std::optional<std::string>& cli_pattern, const FrameName& frame,
                              std::size_t index, const Program& program) {
  const std::string hint =
      "choose a name ending in .pdf, .svg, .png, .hpgl, .gcode, .steps, .json, .jsonl, .dxf, .off, .obj or "
      ".stl that is not an input "
      "file";
  OutputTarget target;
  if (cli_pattern) {
    target.path = has_frame_field(*cli_pattern) ? substitute_frame(*cli_pattern, frame.frame) : *cli_pattern;
    const std::string problem = output_problem(target.path, program);
    if (!problem.empty()) throw RunError("-o " + problem, hint, 64);
  } else if (frame.script_output) {
    const FileAccess& access = program.sources().access();
    const std::string& name = frame.script_output->name;
    target.path = access.output_path(name);
    // A downloaded script must not write over the user's files elsewhere; -o, typed by the user, may.
    if (const std::optional<std::string> refusal = access.write_refusal(target.path, name)) {
      lang::Diagnostic d;
      d.span = frame.script_output->span;
      d.message = "output " + *refusal;
      d.hint = "to write there, name the file on the command line: -o " + name +
               (access.out_dir_given() ? "" : " (or choose the folder with --out-dir DIR)");
      throw EvalError(std::move(d), ErrorKind::Denied);
    }
    const std::string problem = output_problem(target.path, program);
    if (!problem.empty()) fail(frame.script_output->span, "output " + problem, hint);
    target.span = frame.script_output->span;
  } else {
    // "<stdin>" and "<session>" name no file: their output is stdin.pdf, session.pdf.
    std::string stem = fs::path(program.main().source->name()).stem().string();
    std::erase_if(stem, [](char c) { return c == '<' || c == '>'; });
    target.path = program.sources().access().output_path(stem + ".pdf");
    const std::string problem = output_problem(target.path, program);
    if (!problem.empty()) throw RunError(problem, "name the output with -o OUT.pdf", 64);
  }
  target.device = *device_kind_for(target.path);
  target.frames = {index};
  return target;
}

void fail_several_frames(const OutputTarget& target, int frame_a, int frame_b, bool from_cli) {
  const fs::path& path = target.path;
  const std::string message = "'" + path.string() + "' would hold several frames (" +
                              std::to_string(frame_a) + " and " + std::to_string(frame_b) + "), but one " +
                              device_kind_name(target.device) + " file holds one frame";
  const std::string hint = "put {frame:03} in the name to write one file per frame, e.g. '" +
                           path.stem().string() + "-{frame:03}" + path.extension().string() + "'";
  if (target.span) fail(*target.span, "output " + message, hint);
  throw RunError((from_cli ? "-o " : "") + message, hint, 64);
}

std::vector<OutputTarget> plan_outputs(const std::optional<std::string>& cli_pattern,
                                       const std::vector<FrameName>& frames, const Program& program) {
  std::vector<OutputTarget> targets;
  std::map<fs::path, std::size_t> by_path;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    OutputTarget t = target_for_frame(cli_pattern, frames[i], i, program);
    const auto [it, added] = by_path.emplace(t.path, targets.size());
    if (added) {
      targets.push_back(std::move(t));
      continue;
    }
    OutputTarget& target = targets[it->second];
    if (one_frame_per_file(target.device))
      fail_several_frames(target, frames[target.frames[0]].frame, frames[i].frame, cli_pattern.has_value());
    target.frames.push_back(i);
  }
  return targets;
}

void check_writable(const OutputTarget& target) { check_target_directory(target.path); }

}  // namespace hlr::runtime
