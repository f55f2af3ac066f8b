// Every file a run reads — the main script and its includes — parsed once, each with its own FileId, so
// a diagnostic's span finds its file again for printing. Thread-safe: frames evaluated in parallel may
// load includes concurrently; entries never move once added.
#pragma once

#include <deque>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lang/ast.hpp"
#include "lang/diagnostic.hpp"
#include "lang/source.hpp"
#include "runtime/base/file_access.hpp"

namespace hlr::runtime {

struct SourceEntry {
  lang::FileId id = 0;
  std::filesystem::path path;  // absolute and normalised; includes resolve against its directory
  std::shared_ptr<const lang::SourceFile> source;
  std::optional<lang::Script> script;         // set when it parsed without error
  std::vector<lang::Diagnostic> diagnostics;  // syntax errors
};

class SourceTable {
 public:
  // `access` says which files the run's scripts may read and where they may write (file_access.hpp).
  explicit SourceTable(FileAccess access) : access_(std::move(access)) {}
  const FileAccess& access() const { return access_; }

  // Reads and parses `path` once; later calls return the same entry. `display_name` is how diagnostics
  // name the file. Returns nullptr and sets `error` when the file cannot be read.
  const SourceEntry* load(const std::filesystem::path& path, const std::string& display_name,
                          std::string& error);
  // A script given as text (tests, the REPL); `path` is where its includes are resolved from.
  const SourceEntry* add_text(const std::string& display_name, const std::string& text,
                              const std::filesystem::path& path);

  const SourceEntry* entry(lang::FileId id) const;
  const lang::SourceFile* file(lang::FileId id) const;
  // The paths of every file read so far, scripts and imported meshes (an output must not overwrite any
  // of them; watch mode re-renders when one changes).
  std::vector<std::filesystem::path> paths() const;
  // A file read by a built-in (import): one more input of the run.
  void add_input(const std::filesystem::path& path) const;
  // Frees every file's syntax tree; their text stays, for messages (Program::release_syntax).
  void release_syntax();

 private:
  const SourceEntry* add(std::filesystem::path path, const std::string& display_name, std::string text);

  FileAccess access_;
  mutable std::mutex mutex_;
  std::deque<SourceEntry> entries_;  // index = FileId
  std::map<std::filesystem::path, lang::FileId> by_path_;
  mutable std::vector<std::filesystem::path> inputs_;  // imported files, each once
};

// Prints diagnostics, each with its own file's line and caret, notes included (their spans may point
// into other files than the diagnostic's).
void print_diagnostics(std::ostream& out, const std::vector<lang::Diagnostic>& diagnostics,
                       const SourceTable& sources);
// The text `span` covers, "..." when it is not in a known file.
std::string span_text(const SourceTable& sources, const lang::SourceSpan& span);

std::string format_diagnostic(const lang::Diagnostic& diagnostic, const SourceTable& sources);

}  // namespace hlr::runtime
