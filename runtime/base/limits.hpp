// Runaway limits of an evaluation (runtime/LANGUAGE_SPEC.md, "Limits"). One place for every number, one
// wording for every message (Lua's errorlimit): "too many X (the limit is N)". Each is checked where the
// runaway would happen, before the memory or time is spent, and reported at the offending span.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
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

inline constexpr std::size_t kMaxVerticesDrawn = 30'000'000;  // vertices of the solids drawn in one frame
inline constexpr std::size_t kMaxSegments = 20'000'000;       // pieces the hidden-line engine returns
inline constexpr std::size_t kMaxGeometryMb = 16'384;  // estimated memory of the solids one frame makes
// What one face costs from the moment it is made to the frame's file, for the estimate checked before a
// solid is built or a mesh read (measured end to end at about 1 KiB per face on big scenes, bench/README.md).
inline constexpr std::size_t kEstimatedBytesPerFace = 1024;
inline constexpr std::size_t kEstimatedBytesPerMeshByte = 40;  // a mesh file's text, read into a solid

// The limits of one run, each raised (or lowered) by `--limit NAME=N`; the defaults are the constants
// above, generous for every example and bench scene. A script cannot change them.
struct Limits {
  std::uint64_t steps = kMaxSteps;
  std::size_t faces = kMaxFaces;
  std::size_t vertices = kMaxVerticesDrawn;
  std::size_t segments = kMaxSegments;
  std::size_t memory_mb = kMaxGeometryMb;
  std::size_t calls = kMaxCallDepth;
  std::size_t list = kMaxListItems;
  std::size_t string = kMaxStringLength;
  double frame_timeout_s = 0;  // --frame-timeout: 0 = none
};

// The names --limit takes, in the order --help lists them.
inline constexpr const char* kLimitNames[] = {"steps",  "faces", "vertices", "segments",
                                              "memory", "calls", "list",     "string"};

// "too many nested calls (the limit is 256)"
inline std::string limit_message(const std::string& what, std::uint64_t limit) {
  return "too many " + what + " (the limit is " + std::to_string(limit) + ")";
}
// "the frame took longer than --frame-timeout 2.5 s"
inline std::string frame_timeout_message(double seconds) {
  char text[64];
  std::snprintf(text, sizeof text, "the frame took longer than --frame-timeout %g s", seconds);
  return text;
}
// "too many faces built in one frame (the limit is 10000000; --limit faces=N raises it)"
inline std::string limit_message(const std::string& what, std::uint64_t limit, const char* option) {
  return "too many " + what + " (the limit is " + std::to_string(limit) + "; --limit " + option +
         "=N raises it)";
}

}  // namespace hlr::runtime
