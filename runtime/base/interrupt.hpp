// Ctrl-C and SIGTERM while hlrscript works. A handler (InterruptHandler) sets the flag; evaluation
// (Budget::step) and the engine (HlrOptions::cancel, set by every render) check it and stop with
// RenderCancelled; the frame pipeline stops taking frames and keeps the files that are complete. The REPL
// clears the flag before each input and stays; a batch run exits 130. Without a handler installed a
// signal ends the process as usual and the flag stays false. A lock-free atomic flag is what a signal
// handler may touch.
#pragma once

#include <signal.h>

#include <atomic>
#include <initializer_list>
#include <vector>

namespace hlr::runtime {

inline std::atomic<bool>& interrupt_requested() {
  static std::atomic<bool> flag{false};
  return flag;
}

// While alive, the given signals set interrupt_requested() instead of ending the process; the handlers
// before are restored on destruction.
class InterruptHandler {
 public:
  explicit InterruptHandler(std::initializer_list<int> signals);
  ~InterruptHandler();
  InterruptHandler(const InterruptHandler&) = delete;
  InterruptHandler& operator=(const InterruptHandler&) = delete;

 private:
  std::vector<std::pair<int, struct sigaction>> before_;
};

}  // namespace hlr::runtime
