// Helpers for the runtime suites: run a script's text, read a value, get the first error as
// "line:col: message" (the form of tests/lang/diagnostics_test.cpp).
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>

#include "runtime/base/eval_error.hpp"
#include "runtime/base/source_table.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/eval/program.hpp"
#include "runtime/values/format_value.hpp"
#include "tests/support/temp_dir.hpp"

namespace hlr::runtime::test {

using hlr::test::TempDir;

// "PREFIX-TestName" with anything but letters and digits as '-': a scratch folder's name for the test
// running now.
inline std::string scratch_name(const std::string& prefix) {
  std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '-';
  return prefix + "-" + name;
}

// Spans hold offsets; the line and column come from the file the span names.
inline std::string line_col(const lang::Diagnostic& d, const lang::SourceFile& file) {
  const lang::SourcePos at = file.position(d.span.begin);
  return std::to_string(at.line) + ":" + std::to_string(at.column) + ": " + d.message;
}
inline std::string line_col(const lang::Diagnostic& d, const SourceTable& sources) {
  const lang::SourceFile* file = sources.file(d.span.file);
  return file ? line_col(d, *file) : "<no file " + std::to_string(d.span.file) + ">: " + d.message;
}
// For a diagnostic of a script that is gone (a warning of run_ok): its text, a one-file script.
inline std::string line_col(const lang::Diagnostic& d, const std::string& text) {
  return line_col(d, lang::SourceFile(d.span.file, "test.hls", text));
}

// Frame `time` of `text`; a syntax or evaluation error fails the test and yields an empty scene.
inline FrameScene run_ok(const std::string& text, FrameTime time = {}) {
  const auto program = Program::from_text("test.hls", text);
  try {
    return program->evaluate(time);
  } catch (const EvalError& e) {
    std::string shown;
    for (const auto& d : e.diagnostics) shown += format_diagnostic(d, program->sources());
    ADD_FAILURE() << "unexpected error:\n" << shown << e.what();
    return {};
  }
}

// "line:col: message" of the first error, or "<no error>".
inline std::string first_error(const std::string& text, FrameTime time = {}, const Limits& limits = {}) {
  const auto program = Program::from_text("test.hls", text);
  program->set_limits(limits);
  try {
    program->evaluate(time);
  } catch (const EvalError& e) {
    return e.diagnostics.empty() ? std::string(e.what())
                                 : line_col(e.diagnostics.front(), program->sources());
  }
  return "<no error>";
}

// The printed diagnostics of the first error (file:line:col, source line, caret, hint, notes).
inline std::string printed_error(const std::string& text) {
  const auto program = Program::from_text("test.hls", text);
  try {
    program->evaluate({});
  } catch (const EvalError& e) {
    std::string shown;
    for (const auto& d : e.diagnostics) shown += format_diagnostic(d, program->sources());
    return shown;
  }
  return "<no error>";
}

// str() of `expr` evaluated after the statements of `prelude`, or "error: line:col: message".
inline std::string value(const std::string& expr, const std::string& prelude = "") {
  SourceTable table(FileAccess(std::filesystem::current_path(), {}));
  const SourceEntry* entry =
      table.add_text("test.hls", prelude + "\nlet result__ = " + expr + "\n", "test.hls");
  if (!entry->script) return "syntax error: " + line_col(entry->diagnostics.front(), table);
  FrameScene scene;
  Evaluator evaluator(table, scene);
  try {
    evaluator.run(*entry);
    return display(*evaluator.global("result__"), 1 << 20);
  } catch (const EvalError& e) {
    return "error: " + line_col(e.diagnostics.front(), table);
  }
}

}  // namespace hlr::runtime::test
