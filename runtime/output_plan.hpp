// Where the frames go. The name comes from -o (where {frame} and {frame:FMT} are replaced by the frame
// number), else from the script's `output` statement (evaluated per frame), else FILE.pdf in the working
// directory. Frames whose names are equal share one file (PDF pages, JSON frames) in frame order; a
// name that differs per frame gives one file per frame. The extension picks the device.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "runtime/frame_runner.hpp"
#include "runtime/program.hpp"

namespace hlr::runtime {

enum class Device { Pdf, Json };

struct OutputTarget {
  std::filesystem::path path;
  Device device = Device::Pdf;
  std::vector<std::size_t> frames;       // indices into the frames given to plan_outputs, in order
  std::optional<lang::SourceSpan> span;  // the script's `output` name, when the path comes from it
};

struct FrameName {
  int frame = 0;
  std::optional<OutputSetting> script_output;
};

// "pdf, json": for messages.
const char* supported_extensions();
std::optional<Device> device_for(const std::filesystem::path& path);

// True when an -o pattern has a {frame...} field.
bool has_frame_field(const std::string& pattern);
// The -o pattern with {frame} / {frame:FMT} replaced; throws RunError (exit 64) for any other {...}.
std::string substitute_frame(const std::string& pattern, int frame);

// Groups frames by file. A bad -o (unknown extension, the input script itself) throws RunError with exit
// 64; the same mistake in the script's output statement throws EvalError at its span.
std::vector<OutputTarget> plan_outputs(const std::optional<std::string>& cli_pattern,
                                       const std::vector<FrameName>& frames, const Program& program);

struct WriteOptions {
  std::string title;    // PDF metadata and captions: the script's name
  int frame_count = 1;  // of the animation, for captions
};

// Throws DeviceError when the target's directory does not exist: checked before any frame is rendered.
void check_writable(const OutputTarget& target);
// Writes one target atomically. Throws DeviceError.
void write_output(const OutputTarget& target, const std::vector<FrameOutput>& frames,
                  const WriteOptions& options);

}  // namespace hlr::runtime
