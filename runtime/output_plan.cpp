#include "runtime/output_plan.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>

#include "runtime/eval_error.hpp"
#include "runtime/format_value.hpp"

namespace hlr::runtime {

namespace fs = std::filesystem;

const char* supported_extensions() { return "pdf, svg, png, hpgl (or .plt), steps, json"; }

std::optional<Device> device_for(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".pdf") return Device::Pdf;
  if (ext == ".svg") return Device::Svg;
  if (ext == ".png") return Device::Png;
  if (ext == ".hpgl" || ext == ".plt" || ext == ".hpg") return Device::Hpgl;
  if (ext == ".steps") return Device::Steps;
  if (ext == ".json") return Device::Json;
  return std::nullopt;
}

bool single_frame(Device device) {
  return device == Device::Svg || device == Device::Png || device == Device::Hpgl || device == Device::Steps;
}

const char* device_name(Device device) {
  switch (device) {
    case Device::Pdf:
      return "PDF";
    case Device::Svg:
      return "SVG";
    case Device::Png:
      return "PNG";
    case Device::Hpgl:
      return "HPGL";
    case Device::Steps:
      return "plotter-steps";
    case Device::Json:
      return "JSON";
  }
  return "?";
}

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
  if (!device_for(path))
    return "'" + path.string() + "': unknown output type '" + path.extension().string() +
           "'; supported: " + supported_extensions();
  const fs::path target = canonical_or_absolute(path);
  for (const fs::path& input : program.sources().paths())
    if (target == input)
      return "'" + path.string() + "' is an input file of this run; refusing to overwrite it";
  return "";
}

}  // namespace

std::vector<OutputTarget> plan_outputs(const std::optional<std::string>& cli_pattern,
                                       const std::vector<FrameName>& frames, const Program& program) {
  std::vector<OutputTarget> targets;
  std::map<fs::path, std::size_t> by_path;
  const fs::path fallback = fs::path(program.main().source->name()).stem().string() + ".pdf";
  for (std::size_t i = 0; i < frames.size(); ++i) {
    fs::path path;
    std::string problem;
    if (cli_pattern) {
      path = has_frame_field(*cli_pattern) ? substitute_frame(*cli_pattern, frames[i].frame) : *cli_pattern;
      problem = output_problem(path, program);
      if (!problem.empty())
        throw RunError(
            "-o " + problem,
            "choose a name ending in .pdf, .svg, .png, .hpgl, .steps or .json that is not an input file", 64);
    } else if (frames[i].script_output) {
      path = frames[i].script_output->name;
      problem = output_problem(path, program);
      if (!problem.empty())
        fail(frames[i].script_output->span, "output " + problem,
             "choose a name ending in .pdf, .svg, .png, .hpgl, .steps or .json that is not an input file");
    } else {
      path = fallback;
      problem = output_problem(path, program);
      if (!problem.empty()) throw RunError(problem, "name the output with -o OUT.pdf", 64);
    }
    const auto [it, added] = by_path.emplace(path, targets.size());
    if (added) {
      targets.push_back({path, *device_for(path), {}, std::nullopt});
      if (!cli_pattern && frames[i].script_output) targets.back().span = frames[i].script_output->span;
    }
    OutputTarget& target = targets[it->second];
    target.frames.push_back(i);
    if (target.frames.size() == 2 && single_frame(target.device)) {
      const std::string message = "'" + path.string() + "' would hold several frames (" +
                                  std::to_string(frames[target.frames[0]].frame) + " and " +
                                  std::to_string(frames[i].frame) + "), but one " +
                                  device_name(target.device) + " file holds one frame";
      const std::string hint = "put {frame:03} in the name to write one file per frame, e.g. '" +
                               path.stem().string() + "-{frame:03}" + path.extension().string() + "'";
      if (target.span) fail(*target.span, "output " + message, hint);
      throw RunError((cli_pattern ? "-o " : "") + message, hint, 64);
    }
  }
  return targets;
}

}  // namespace hlr::runtime
