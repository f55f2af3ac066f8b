// What a script may touch (README, "What a script can touch"). Scripts and meshes come from other
// people, so a script reads only below its own folder, the library modules and the folders the user
// allows with --allow-path, and the outputs it names go only below the working directory (or --out-dir).
// The command line's own -o may name any path: the user typed it. Every check resolves symbolic links
// and `..` first and is made before the file is opened, so a refused file is never read and no message
// quotes it. (A link swapped between the check and the read is outside what this guards against: the
// files of the allowed folders are the user's.)
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace hlr::runtime {

// The folders a run grants, as given on the command line.
struct AccessOptions {
  std::vector<std::filesystem::path> allow_paths;  // --allow-path DIR (repeatable)
  std::optional<std::filesystem::path> out_dir;    // --out-dir DIR
};

class FileAccess {
 public:
  // Reads below the main script's folder, the library modules and `options.allow_paths`; script-named
  // outputs below `options.out_dir`, else the working directory.
  FileAccess(const std::filesystem::path& script_directory, const AccessOptions& options);

  // Why the script may not read `path` (an include or an import, already joined to its base), or nullopt.
  // `written` is the path as the script wrote it, for the message.
  std::optional<std::string> read_refusal(const std::filesystem::path& path,
                                          const std::string& written) const;
  // The option that would allow reading `path`: "--allow-path DIR".
  std::string allow_hint(const std::filesystem::path& path) const;

  // Where an output the script names goes: below the output folder.
  std::filesystem::path output_path(const std::string& name) const;
  // Why the script may not write `path` (from output_path), or nullopt.
  std::optional<std::string> write_refusal(const std::filesystem::path& path,
                                           const std::string& written) const;
  bool out_dir_given() const { return out_dir_given_; }

  const std::vector<std::filesystem::path>& read_roots() const { return read_roots_; }
  const std::filesystem::path& output_root() const { return output_root_; }

 private:
  std::vector<std::filesystem::path> read_roots_;  // canonical
  std::filesystem::path output_root_;              // canonical
  bool out_dir_given_ = false;
};

// `path` made absolute, with `..` and every symbolic link of its existing part resolved.
std::filesystem::path resolved_path(const std::filesystem::path& path);
// True when `path` is `root` or below it (both resolved).
bool is_below(const std::filesystem::path& path, const std::filesystem::path& root);

// The folder of the library modules (`include "std/NAME.hls"`): HLRSCRIPT_STDLIB; else, installed,
// ../share/hlrscript/modules beside the running program's folder (so a moved or packaged install finds its
// own); else the source tree's, for a program run from its build folder.
std::filesystem::path stdlib_module_directory();

// The modules' files there (*.hls), sorted by name; none when the folder cannot be read.
std::vector<std::filesystem::path> library_module_files();

}  // namespace hlr::runtime
