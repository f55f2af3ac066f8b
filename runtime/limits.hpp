// Runaway limits of an evaluation (runtime/LANGUAGE_SPEC.md, "Limits"). One place for every number, one
// wording for every message (Lua's errorlimit): "too many X (the limit is N)". Each is checked where the
// runaway would happen, before the memory or time is spent, and reported at the offending span.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace hlr::runtime {

inline constexpr std::size_t kMaxCallDepth = 256;            // nested calls of user functions
inline constexpr std::uint64_t kMaxSteps = 10'000'000;       // expressions + statements per frame
inline constexpr std::size_t kMaxFaces = 10'000'000;         // faces built, and faces drawn, per frame
inline constexpr std::size_t kMaxListItems = 10'000'000;     // items of one list (or range, or outline)
inline constexpr std::size_t kMaxStringLength = 10'000'000;  // bytes of one string
inline constexpr std::size_t kMaxFrames = 10'000;            // animate frames N
inline constexpr std::size_t kMaxIncludeDepth = 32;          // include inside include inside ...
// Native recursion of the evaluator (expression and block nesting times call depth). The parser caps
// an expression at 256 levels and blocks at 64, so a legal script stays far below; the cap only turns
// an unforeseen path into an error instead of a stack overflow. The evaluation thread's stack is sized
// for it (big_stack.cpp).
inline constexpr std::uint64_t kInterruptCheckSteps = 4096;  // evaluation steps between Ctrl-C checks
inline constexpr std::size_t kMaxEvalDepth = 100'000;

// "too many nested calls (the limit is 256)"
inline std::string limit_message(const std::string& what, std::uint64_t limit) {
  return "too many " + what + " (the limit is " + std::to_string(limit) + ")";
}

}  // namespace hlr::runtime
