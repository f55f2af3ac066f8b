// The counters behind the runaway limits of one evaluation (limits.hpp): steps, faces, nesting.
// Every charge that goes over its limit is an error at the span that asked for it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/hlr/render_frame.hpp"
#include "lang/source.hpp"
#include "runtime/eval_error.hpp"
#include "runtime/interrupt.hpp"
#include "runtime/limits.hpp"

namespace hlr::runtime {

class Budget {
 public:
  void step(const lang::SourceSpan& span, std::uint64_t n = 1) {
    steps_ += n;
    if (steps_ > kMaxSteps)
      fail(span, limit_message("evaluation steps in one frame", kMaxSteps),
           "is a loop or a recursion running away? Large lists and strings cost one step per item");
    if (steps_ >= next_interrupt_check_) {
      next_interrupt_check_ = steps_ + kInterruptCheckSteps;
      if (interrupt_requested().load(std::memory_order_relaxed)) throw RenderCancelled();
    }
  }
  // Faces of solids made (generators, `solid` statements); checked before the solid is built.
  void charge_faces_built(const lang::SourceSpan& span, std::size_t n) {
    built_ += n;
    if (n > kMaxFaces || built_ > kMaxFaces)
      fail(span, limit_message("faces built in one frame", kMaxFaces), "use fewer or coarser solids");
  }
  void charge_faces_drawn(const lang::SourceSpan& span, std::size_t n) {
    drawn_ += n;
    if (drawn_ > kMaxFaces)
      fail(span, limit_message("faces drawn in one frame", kMaxFaces), "draw fewer or coarser solids");
  }
  static void check_list_size(const lang::SourceSpan& span, std::size_t n) {
    if (n > kMaxListItems) fail(span, limit_message("items in a list", kMaxListItems));
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
  std::vector<lang::Diagnostic> warnings_;
};

}  // namespace hlr::runtime
