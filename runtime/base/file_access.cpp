#include "runtime/base/file_access.hpp"

#include <algorithm>
#include <cstdlib>

namespace hlr::runtime {

namespace fs = std::filesystem;

fs::path resolved_path(const fs::path& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  if (ec) return path.lexically_normal();
  fs::path p = fs::weakly_canonical(absolute, ec);
  return ec ? absolute.lexically_normal() : p.lexically_normal();
}

bool is_below(const fs::path& path, const fs::path& root) {
  // Component by component, so that /work/a is not taken to be below /work/ab. A root that ends in a
  // separator ("/tmp/") has an empty last component, which is not one to compare.
  auto r = root.begin(), r_end = root.end();
  if (r != r_end && std::prev(r_end)->empty()) --r_end;
  auto p = path.begin();
  for (; r != r_end; ++r, ++p)
    if (p == path.end() || *p != *r) return false;
  return true;
}

fs::path stdlib_module_directory() {
  if (const char* dir = std::getenv("HLRSCRIPT_STDLIB"); dir && *dir) return dir;
  // Found once: the program does not move while it runs.
  static const fs::path found = [] {
    std::error_code ec;
    const fs::path program = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
      const fs::path installed = program.parent_path().parent_path() / HLR_INSTALLED_MODULES;
      if (fs::is_directory(installed, ec)) return installed.lexically_normal();
    }
    return fs::path(HLR_STDLIB_MODULES);
  }();
  return found;
}

FileAccess::FileAccess(const fs::path& script_directory, const AccessOptions& options) {
  read_roots_.push_back(resolved_path(script_directory));
  read_roots_.push_back(resolved_path(stdlib_module_directory()));
  for (const fs::path& p : options.allow_paths) read_roots_.push_back(resolved_path(p));
  out_dir_given_ = options.out_dir.has_value();
  output_root_ = resolved_path(options.out_dir ? *options.out_dir : fs::current_path());
}

std::optional<std::string> FileAccess::read_refusal(const fs::path& path, const std::string& written) const {
  const fs::path target = resolved_path(path);
  if (std::any_of(read_roots_.begin(), read_roots_.end(),
                  [&](const fs::path& r) { return is_below(target, r); }))
    return std::nullopt;
  return "'" + written + "': it is outside the folders this script may read (" +
         read_roots_.front().string() + " and the library modules" +
         (read_roots_.size() > 2 ? ", and those of --allow-path" : "") + ")";
}

std::string FileAccess::allow_hint(const fs::path& path) const {
  return "if you trust this script, run it with --allow-path " + resolved_path(path).parent_path().string();
}

fs::path FileAccess::output_path(const std::string& name) const {
  return out_dir_given_ ? (output_root_ / name).lexically_normal() : fs::path(name);
}

std::optional<std::string> FileAccess::write_refusal(const fs::path& path, const std::string& written) const {
  if (is_below(resolved_path(path), output_root_)) return std::nullopt;
  return "'" + written + "': it is outside the folder a script's outputs go to (" + output_root_.string() +
         (out_dir_given_ ? ", from --out-dir)" : ", the working directory)");
}

std::vector<fs::path> library_module_files() {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(stdlib_module_directory(), ec))
    if (e.path().extension() == ".hls") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace hlr::runtime
