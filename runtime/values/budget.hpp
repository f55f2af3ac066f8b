// The counters behind the runaway limits of one evaluation (limits.hpp): steps, faces, nesting.
// Every charge that goes over its limit is an error at the span that asked for it.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/hlr/render_frame.hpp"
#include "lang/source.hpp"
#include "runtime/base/eval_error.hpp"
#include "runtime/base/interrupt.hpp"
#include "runtime/base/limits.hpp"

namespace hlr::runtime {

class Budget {
 public:
  explicit Budget(const Limits& limits = {})
      : limits_(limits),
        deadline_(limits.frame_timeout_s > 0
                      ? std::chrono::steady_clock::now() +
                            std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                std::chrono::duration<double>(limits.frame_timeout_s))
                      : std::chrono::steady_clock::time_point::max()) {}

  const Limits& limits() const { return limits_; }
  // When the frame's --frame-timeout runs out (time_point::max() without one): the engine and the planner
  // stop at it too.
  std::chrono::steady_clock::time_point deadline() const { return deadline_; }

  void step(const lang::SourceSpan& span, std::uint64_t n = 1) {
    steps_ += n;
    if (steps_ > limits_.steps)
      fail(span, limit_message("evaluation steps in one frame", limits_.steps, "steps"),
           "is a loop or a recursion running away? Large lists and strings cost one step per item");
    if (steps_ >= next_interrupt_check_) {
      next_interrupt_check_ = steps_ + kInterruptCheckSteps;
      if (interrupt_requested().load(std::memory_order_relaxed)) throw RenderCancelled();
      if (std::chrono::steady_clock::now() > deadline_)
        fail(span, frame_timeout_message(limits_.frame_timeout_s) + " while evaluating the script",
             "is a loop running away? --frame-timeout SECONDS raises the limit");
    }
  }
  // Faces of solids made (generators, `solid` statements); checked before the solid is built, with the
  // memory the solid will take from here to the file.
  void charge_faces_built(const lang::SourceSpan& span, std::size_t n) {
    built_ += n;
    if (n > limits_.faces || built_ > limits_.faces)
      fail(span, limit_message("faces built in one frame", limits_.faces, "faces"),
           "use fewer or coarser solids");
    charge_memory(span, static_cast<double>(n) * kEstimatedBytesPerFace, "solids made");
  }
  // Memory a solid will need, estimated before it is built or read (a mesh from its file's size).
  void charge_memory(const lang::SourceSpan& span, double bytes, const char* what) {
    memory_ += bytes;
    const double limit = static_cast<double>(limits_.memory_mb) * (1 << 20);
    if (memory_ > limit)
      fail(span,
           std::string("the ") + what + " would need about " +
               std::to_string(static_cast<std::uint64_t>(memory_ / (1 << 20))) +
               " MB in this frame (the limit is " + std::to_string(limits_.memory_mb) +
               " MB; --limit memory=MB raises it)",
           "use fewer or coarser solids");
  }
  // The same check for memory about to be spent once (a mesh file read into a solid), not kept: the
  // solid's faces are charged when it is made.
  void check_memory_ahead(const lang::SourceSpan& span, double bytes, const char* what) {
    memory_ += bytes;
    try {
      charge_memory(span, 0, what);
    } catch (...) {
      memory_ -= bytes;
      throw;
    }
    memory_ -= bytes;
  }
  void charge_faces_drawn(const lang::SourceSpan& span, std::size_t faces, std::size_t vertices = 0) {
    drawn_ += faces;
    vertices_ += vertices;
    if (drawn_ > limits_.faces)
      fail(span, limit_message("faces drawn in one frame", limits_.faces, "faces"),
           "draw fewer or coarser solids");
    if (vertices_ > limits_.vertices)
      fail(span, limit_message("vertices drawn in one frame", limits_.vertices, "vertices"),
           "draw fewer or coarser solids");
  }
  void check_list_size(const lang::SourceSpan& span, std::size_t n) const {
    if (n > limits_.list) fail(span, limit_message("items in a list", limits_.list, "list"));
  }
  void check_string_size(const lang::SourceSpan& span, std::size_t n) const {
    if (n > limits_.string) fail(span, limit_message("bytes in a string", limits_.string, "string"));
  }

  // Warnings raised by built-ins (an imported mesh repaired); the evaluator reports them with its own.
  void warn(lang::Diagnostic warning) { warnings_.push_back(std::move(warning)); }
  std::vector<lang::Diagnostic> take_warnings() { return std::move(warnings_); }

  std::uint64_t steps() const { return steps_; }
  std::size_t faces_built() const { return built_; }
  std::size_t faces_drawn() const { return drawn_; }

 private:
  std::uint64_t steps_ = 0;
  std::uint64_t next_interrupt_check_ = 0;
  std::size_t built_ = 0;
  std::size_t drawn_ = 0;
  std::size_t vertices_ = 0;
  double memory_ = 0;
  Limits limits_;
  std::chrono::steady_clock::time_point deadline_;
  std::vector<lang::Diagnostic> warnings_;
};

}  // namespace hlr::runtime
