// The frame pipeline: from a loaded script to its files, every frame on every core (runtime/README.md
// draws the path). Frames are independent, so each one's whole journey — evaluate, resolve its
// settings, hidden lines, page layout and pen plan, device encoding — runs beside the others'; only
// appending to the files happens one frame after another, in frame order. A bounded number of frames is
// in flight, so memory stays flat however long the sequence. Output bytes do not depend on --jobs.
// Files are written beside their targets and renamed into place when complete. When a frame fails, the
// run stops (or, with keep_going, renders the rest) and keeps every file that is whole: each file all of
// whose frames succeeded and that no failed frame could have gone to. A file holding several frames (PDF
// pages, JSON) is kept only when the failed frames' files are known and differ from it (-o names them,
// or the failure came after the frame's file was resolved), or when every frame so far went to a file of
// its own (a script's output name with the frame in it): a multi-page file is whole or absent.
#pragma once

#include <cstddef>
#include <exception>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/device/page/atomic_file.hpp"
#include "core/hlr/visible_segment.hpp"
#include "core/plan/pen_plan.hpp"
#include "lang/diagnostic.hpp"
#include "runtime/eval/program.hpp"
#include "runtime/pipeline/output_settings.hpp"
#include "runtime/pipeline/run_error.hpp"

namespace hlr::runtime {

// A device's failure for one file: reported at the script's output statement when it named the file.
struct OutputError : DeviceError {
  OutputError(const std::string& message, OutputTarget target_)
      : DeviceError(message), target(std::move(target_)) {}
  OutputTarget target;
};

// The run was stopped (Ctrl-C, SIGTERM: interrupt_requested()) after `frames_done` of the frames asked
// for, in order. The files that were complete are in place (`files`); the rest were removed.
struct RunInterrupted : std::runtime_error {
  RunInterrupted(std::vector<int> done, std::vector<std::filesystem::path> written, bool removed)
      : std::runtime_error("interrupted"),
        frames_done(std::move(done)),
        files(std::move(written)),
        removed_partial(removed) {}
  std::vector<int> frames_done;
  std::vector<std::filesystem::path> files;
  bool removed_partial;  // a file still being written was removed
};

// Some frames failed (a script error in frame k, a file that could not be written) while others went
// through. Thrown when anything was kept or more than one frame failed; a single failure that kept
// nothing is rethrown as itself. `failures` holds each failed frame's own exception (EvalError with "(in
// frame k)", RunError, OutputError), in frame order.
struct FramesFailed : std::runtime_error {
  struct Failure {
    int frame;
    std::exception_ptr error;
  };
  FramesFailed(std::vector<Failure> failed, std::vector<int> done, std::vector<std::filesystem::path> written)
      : std::runtime_error("frames failed"),
        failures(std::move(failed)),
        frames_done(std::move(done)),
        files(std::move(written)) {}
  std::vector<Failure> failures;
  std::vector<int> frames_done;              // the frames in the kept files (or rendered, without files)
  std::vector<std::filesystem::path> files;  // kept, each whole
};

struct PipelineOptions {
  RunSettings run;
  unsigned jobs = 0;           // threads for everything (frames and the work inside them); 0: one per core
  bool render = true;          // false: evaluate and resolve cameras and files only (hlrscript check)
  bool write = true;           // false: render and plan, but write no file (tests, the REPL)
  bool keep_segments = false;  // FrameRecord::segments holds the frame's pieces
  bool keep_records = true;    // PipelineResult::frames has every frame's record (else totals only)
  bool keep_going = false;     // --keep-going: a failed frame does not stop the others (FramesFailed)
  // Called in frame order as each frame is written (done of total): the command's progress line.
  std::function<void(std::size_t done, std::size_t total)> on_frame;
};

// What became of one frame, in frame order.
struct FrameRecord {
  FrameTime time;
  std::string camera_name;
  std::vector<std::string> object_names;  // by VisibleSegment::object
  std::size_t faces = 0;                  // faces drawn
  std::size_t segments = 0;               // pieces the engine returned (hidden ones included when on)
  HiddenStyle hidden;
  FrameStats stats;
  double evaluate_seconds = 0, render_seconds = 0;
  std::filesystem::path path;  // the file it went to
  PlanStats plan;
  std::size_t visible_segments = 0;           // pieces given to the pen plan
  std::vector<std::size_t> level_pieces;      // by occlusion level: [k] the hidden pieces of level k
  double encode_seconds = 0;                  // the device's encode() of the planned page
  std::size_t encoded_bytes = 0;              // what encode() made for the file
  std::vector<VisibleSegment> kept_segments;  // with keep_segments only
};

struct PipelineResult {
  std::vector<FrameRecord> frames;                       // in the order of `frames` given; with keep_records
  std::size_t frame_count = 0, faces = 0, segments = 0;  // totals over every frame
  std::vector<std::filesystem::path> files;  // written (or that would be), in order of first frame
  std::vector<lang::Diagnostic> warnings;    // from every frame, each distinct one once
};

// Runs `frames` of `program`. `first` is frame 0's scene when the caller has evaluated it already; `fps`
// comes from its animate statement. Throws EvalError or RunError of the lowest failing frame (for an
// animation the message names the frame), OutputError for a device's failure — or FramesFailed with every
// failure when some files were kept or several frames failed (see above) — RunInterrupted when
// interrupt_requested() stopped it: then each file that holds only frames done is kept whole (a file per
// frame, and any file a later frame did not go to), the file still being written is removed.
PipelineResult run_pipeline(const Program& program, const std::vector<int>& frames, double fps,
                            const PipelineOptions& options, std::optional<FrameScene> first = std::nullopt);

}  // namespace hlr::runtime
