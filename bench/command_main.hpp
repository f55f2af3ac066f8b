// The benchmarks' main(): Google Benchmark under the command's allocator policy (runtime/cli/main.cpp keeps
// freed memory for reuse), so that what is measured here costs what it costs in `hlrscript`. Without it
// every iteration pays for faulting in fresh pages again, which on this machine is most of a render's time
// (city 10^5: 382 ms against 213 ms).
#pragma once

#include <benchmark/benchmark.h>

#include "runtime/base/allocator_policy.hpp"

#define HLR_BENCHMARK_MAIN()                                          \
  int main(int argc, char** argv) {                                   \
    hlr::runtime::keep_freed_memory();                                \
    benchmark::Initialize(&argc, argv);                               \
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1; \
    benchmark::RunSpecifiedBenchmarks();                              \
    benchmark::Shutdown();                                            \
    return 0;                                                         \
  }
