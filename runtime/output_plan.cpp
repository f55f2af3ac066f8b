#include "runtime/output_plan.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>

#include "core/device/atomic_file.hpp"
#include "core/device/json_device.hpp"
#include "core/device/pdf_device.hpp"
#include "runtime/eval_error.hpp"
#include "runtime/format_value.hpp"

namespace hlr::runtime {

namespace fs = std::filesystem;

const char* supported_extensions() { return "pdf, json"; }

std::optional<Device> device_for(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".pdf") return Device::Pdf;
  if (ext == ".json") return Device::Json;
  return std::nullopt;
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
        throw RunError("-o " + problem, "choose a name ending in .pdf or .json that is not an input file",
                       64);
    } else if (frames[i].script_output) {
      path = frames[i].script_output->name;
      problem = output_problem(path, program);
      if (!problem.empty())
        fail(frames[i].script_output->span, "output " + problem,
             "choose a name ending in .pdf or .json that is not an input file");
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
    targets[it->second].frames.push_back(i);
  }
  return targets;
}

namespace {

std::string caption_for(const FrameOutput& f, const WriteOptions& options) {
  char buf[256];
  if (options.frame_count > 1)
    std::snprintf(buf, sizeof buf, "%s   frame %d of %d (t = %.4g, %.4g s)   camera %s",
                  options.title.c_str(), f.time.frame, options.frame_count, f.time.t, f.time.time,
                  f.camera_name.c_str());
  else
    std::snprintf(buf, sizeof buf, "%s   camera %s", options.title.c_str(), f.camera_name.c_str());
  return buf;
}

void write_pdf_target(const OutputTarget& target, const std::vector<FrameOutput>& frames,
                      const WriteOptions& options) {
  std::vector<DrawingPage> pages;
  pages.reserve(target.frames.size());
  for (const std::size_t i : target.frames)
    pages.push_back({frames[i].segments, frames[i].camera.frame, caption_for(frames[i], options)});
  PdfOptions pdf;
  pdf.title = options.title;
  if (const auto& paper = frames[target.frames.front()].paper) {
    pdf.page_width_mm = paper->paper.width_mm;
    pdf.page_height_mm = paper->paper.height_mm;
  }
  write_pdf(target.path, pages, pdf);
}

// The JSON device (core/device/json_device.hpp, schema hlrscript.lines/1): one entry per frame.
void write_json_target(const OutputTarget& target, const std::vector<FrameOutput>& frames,
                       const WriteOptions& options) {
  std::vector<JsonFrame> json;
  json.reserve(target.frames.size());
  JsonOptions o;
  o.title = options.title;
  for (const std::size_t i : target.frames) {
    const FrameOutput& f = frames[i];
    json.push_back({f.time.frame, f.time.time, f.camera, f.segments, f.object_names});
    o.include_hidden = o.include_hidden || f.hidden;
  }
  if (const auto& paper = frames[target.frames.front()].paper) o.paper = paper->paper;
  write_json(target.path, json, o);
}

}  // namespace

void check_writable(const OutputTarget& target) {
  const fs::path dir = target.path.has_parent_path() ? target.path.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec))  // worded as write_atomically() words it
    throw DeviceError("cannot write '" + target.path.string() + "': directory '" + dir.string() +
                      "' does not exist");
}

void write_output(const OutputTarget& target, const std::vector<FrameOutput>& frames,
                  const WriteOptions& options) {
  if (target.device == Device::Pdf)
    write_pdf_target(target, frames, options);
  else
    write_json_target(target, frames, options);
}

}  // namespace hlr::runtime
