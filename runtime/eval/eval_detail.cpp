#include "runtime/eval/eval_detail.hpp"

namespace hlr::runtime {

namespace {

constexpr std::size_t kMaxNotes = 4;

}  // namespace

void add_note(EvalError& error, const lang::SourceSpan& span, const std::string& message) {
  if (error.diagnostics.empty()) return;
  lang::Diagnostic& d = error.diagnostics.front();
  if (d.span == span || (!d.notes.empty() && d.notes.back().span == span)) return;  // says nothing new
  if (d.notes.size() < kMaxNotes) d.notes.push_back({span, message});
}

}  // namespace hlr::runtime
