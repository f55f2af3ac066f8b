#include "runtime/base/source_table.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <ostream>

#include "lang/parser.hpp"

namespace hlr::runtime {

namespace fs = std::filesystem;

namespace {

fs::path normalised(const fs::path& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? fs::absolute(path).lexically_normal() : p;
}

}  // namespace

const SourceEntry* SourceTable::load(const fs::path& path, const std::string& display_name,
                                     std::string& error) {
  const fs::path key = normalised(path);
  {
    std::lock_guard lock(mutex_);
    const auto it = by_path_.find(key);
    if (it != by_path_.end()) return &entries_[it->second];
  }
  std::error_code ec;
  if (fs::is_directory(key, ec)) {
    error = "cannot read '" + display_name + "': it is a directory";
    return nullptr;
  }
  std::ifstream in(key, std::ios::binary);
  if (!in) {
    error = "cannot read '" + display_name + "': " + std::strerror(errno);
    return nullptr;
  }
  // Read straight into the string the SourceFile keeps: a script of 100 MB is not copied on the way.
  std::string text;
  const auto size = fs::file_size(key, ec);
  if (!ec) text.reserve(static_cast<std::size_t>(size));
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
  if (in.bad()) {
    error = "cannot read '" + display_name + "': read error";
    return nullptr;
  }
  return add(key, display_name, std::move(text));
}

const SourceEntry* SourceTable::add_text(const std::string& display_name, const std::string& text,
                                         const fs::path& path) {
  return add(fs::absolute(path).lexically_normal(), display_name, text);
}

const SourceEntry* SourceTable::add(fs::path path, const std::string& display_name, std::string text) {
  std::lock_guard lock(mutex_);
  const auto it = by_path_.find(path);
  if (it != by_path_.end()) return &entries_[it->second];  // another thread loaded it meanwhile
  const auto id = static_cast<lang::FileId>(entries_.size());
  lang::ParseResult parsed =
      lang::parse(std::make_shared<const lang::SourceFile>(id, display_name, std::move(text)));
  SourceEntry& e = entries_.emplace_back();
  e.id = id;
  e.path = path;
  e.source = std::move(parsed.source);
  e.script = std::move(parsed.script);
  e.diagnostics = std::move(parsed.diagnostics);
  by_path_.emplace(std::move(path), id);
  return &e;
}

const SourceEntry* SourceTable::entry(lang::FileId id) const {
  std::lock_guard lock(mutex_);
  return id < entries_.size() ? &entries_[id] : nullptr;
}

const lang::SourceFile* SourceTable::file(lang::FileId id) const {
  const SourceEntry* e = entry(id);
  return e ? e->source.get() : nullptr;
}

std::vector<fs::path> SourceTable::paths() const {
  std::lock_guard lock(mutex_);
  std::vector<fs::path> out;
  for (const SourceEntry& e : entries_) out.push_back(e.path);
  out.insert(out.end(), inputs_.begin(), inputs_.end());
  return out;
}

void SourceTable::add_input(const fs::path& path) const {
  std::lock_guard lock(mutex_);
  if (std::find(inputs_.begin(), inputs_.end(), path) == inputs_.end()) inputs_.push_back(path);
}

void SourceTable::release_syntax() {
  std::lock_guard lock(mutex_);
  for (SourceEntry& entry : entries_) entry.script.reset();
}

std::string format_diagnostic(const lang::Diagnostic& diagnostic, const SourceTable& sources) {
  const lang::SourceFile* file = sources.file(diagnostic.span.file);
  if (!file) return std::string(lang::to_string(diagnostic.severity)) + ": " + diagnostic.message + "\n";
  lang::Diagnostic main = diagnostic;
  main.notes.clear();
  std::string out = lang::format(main, *file);
  for (const lang::DiagnosticNote& note : diagnostic.notes) {
    const lang::SourceFile* note_file = sources.file(note.span.file);
    if (!note_file) continue;
    lang::Diagnostic as_note;
    as_note.severity = lang::Severity::Note;
    as_note.span = note.span;
    as_note.message = note.message;
    out += lang::format(as_note, *note_file);
  }
  return out;
}

void print_diagnostics(std::ostream& out, const std::vector<lang::Diagnostic>& diagnostics,
                       const SourceTable& sources) {
  for (const lang::Diagnostic& d : diagnostics) out << format_diagnostic(d, sources);
}

std::string span_text(const SourceTable& sources, const lang::SourceSpan& span) {
  const lang::SourceFile* file = sources.file(span.file);
  if (!file || span.end < span.begin || span.end > file->text().size()) return "...";
  return file->text().substr(span.begin, span.end - span.begin);
}

}  // namespace hlr::runtime
