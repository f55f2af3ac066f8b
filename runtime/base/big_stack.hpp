// Runs a function on a thread with a large stack. The evaluator recurses on the script's nesting;
// its depth counters (limits.hpp) bound that recursion, and this stack is sized so the bound is always
// reached before the stack's end — also under sanitizers, whose frames are several times larger.
#pragma once

#include <cstddef>
#include <functional>

namespace hlr::runtime {

inline constexpr std::size_t kEvaluationStackBytes = std::size_t{512} << 20;  // reserved, touched on demand

// Calls fn() on a new thread with `stack_bytes` of stack, waits for it and rethrows what it threw. If no
// such thread can be made, calls fn() on the calling thread.
void run_on_big_stack(const std::function<void()>& fn, std::size_t stack_bytes = kEvaluationStackBytes);

}  // namespace hlr::runtime
