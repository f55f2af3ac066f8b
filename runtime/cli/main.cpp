// hlrscript: the command-line entry point. Everything happens in run_cli (runtime/cli/cli.hpp).
#include <unistd.h>

#include <iostream>

#include "runtime/base/allocator_policy.hpp"
#include "runtime/base/heap_warmer.hpp"
#include "runtime/cli/cli.hpp"
#include "runtime/pipeline/script_run.hpp"

int main(int argc, char** argv) {
  hlr::runtime::heap_on_huge_pages(argv);
  hlr::runtime::keep_freed_memory();
  hlr::runtime::warm_heap_ahead();
  hlr::runtime::leave_program_at_exit();
  return hlr::runtime::run_cli(argc, argv, std::cin, ::isatty(STDIN_FILENO) == 1, std::cout, std::cerr,
                               ::isatty(STDERR_FILENO) == 1);
}
