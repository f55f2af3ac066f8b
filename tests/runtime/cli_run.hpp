// The command in-process for the CLI and device suites: run_cli with captured streams, and a file's
// bytes.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "runtime/cli/cli.hpp"

namespace hlr::runtime::test {

struct CliResult {
  int code;
  std::string out, err;
};

// `hlrscript ARGS...` through run_cli.
inline CliResult run(std::vector<std::string> args) {
  args.insert(args.begin(), "hlrscript");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  std::ostringstream out, err;
  const int code = run_cli(static_cast<int>(argv.size()), argv.data(), out, err);
  return {code, out.str(), err.str()};
}

// `hlrscript ARGS...` with `input` on standard input (not a terminal).
inline CliResult run_with_input(std::vector<std::string> args, const std::string& input) {
  args.insert(args.begin(), "hlrscript");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  std::istringstream in(input);
  std::ostringstream out, err;
  const int code = run_cli(static_cast<int>(argv.size()), argv.data(), in, false, out, err);
  return {code, out.str(), err.str()};
}

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace hlr::runtime::test
