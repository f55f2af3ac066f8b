#include "runtime/base/interrupt.hpp"

namespace hlr::runtime {

namespace {
void on_signal(int) { interrupt_requested().store(true); }
}  // namespace

InterruptHandler::InterruptHandler(std::initializer_list<int> signals) {
  static_assert(std::atomic<bool>::is_always_lock_free, "a signal handler may only touch lock-free atomics");
  for (const int signal : signals) {
    struct sigaction a {};
    a.sa_handler = on_signal;
    sigemptyset(&a.sa_mask);
    struct sigaction old {};
    ::sigaction(signal, &a, &old);
    before_.emplace_back(signal, old);
  }
}

InterruptHandler::~InterruptHandler() {
  for (const auto& [signal, old] : before_) ::sigaction(signal, &old, nullptr);
}

}  // namespace hlr::runtime
