// import("mesh.off", crease: 0, contours: "edges"): a solid from a mesh file (OFF, OBJ, STL, Albers'
// .VER/.SUR), its path relative to the script that names it. The script runs once per frame, so meshes are
// cached for the process by resolved path, crease angle, contours, size and modification time: an animation
// reads each file once.
#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>

#include "core/format_number.hpp"
#include "runtime/base/file_access.hpp"
#include "runtime/builtins/builtins.hpp"
#include "runtime/values/format_value.hpp"
#include "stdlib/mesh_import.hpp"

namespace hlr::runtime {
namespace {

namespace fs = std::filesystem;

struct CachedMesh {
  std::shared_ptr<const Solid> solid;
  std::vector<stdlib::MeshProblem> warnings;
};

using CacheKey = std::tuple<std::string, double, bool, std::uintmax_t, fs::file_time_type::rep>;

std::mutex cache_mutex;
std::map<CacheKey, CachedMesh> cache;

// The mesh file as the script names it: the importer reports the resolved path (and, for an Albers pair,
// maybe the partner file beside it), the user wrote a path relative to the script.
std::string shown_file(const std::string& reported, const fs::path& resolved, const std::string& written) {
  const fs::path r(reported);
  if (r == resolved) return written;
  if (r.parent_path() == resolved.parent_path())
    return (fs::path(written).parent_path() / r.filename()).string();
  return reported;
}

std::string problem_text(const stdlib::MeshProblem& p, const fs::path& resolved, const std::string& written) {
  std::string where = shown_file(p.file, resolved, written);
  if (p.line > 0) where += ":" + std::to_string(p.line);
  if (p.column > 0) where += ":" + std::to_string(p.column);
  return where + ": " + p.message;
}

[[noreturn]] void fail_import(const lang::SourceSpan& span, const std::string& message,
                              const std::string& hint, ErrorKind kind) {
  lang::Diagnostic d;
  d.span = span;
  d.message = message;
  d.hint = hint;
  throw EvalError(std::move(d), kind);
}

const ParamList kImportParams = {required("path", kinds(ValueKind::String)),
                                 optional("crease", kinds(ValueKind::Number), Value::number(0)),
                                 contours_param()};

Value import_(CallArgs& call) {
  const Bound b = call.bind(kImportParams);
  const std::string written = b.value(0).as_string();
  const double crease = b.number(1);
  if (!(crease >= 0 && crease <= 180))
    b.fail(1, "must be between 0 and 180 degrees (got " + format_for_message(crease) + ")");
  const bool smooth = smooth_contours(b, 2);
  if (written.empty()) b.fail(0, "is empty; name a mesh file such as \"part.off\"");

  fs::path path(written);
  if (path.is_relative()) path = call.script_directory() / path;
  // Before anything is asked of the file, even whether it exists (file_access.hpp).
  if (const FileAccess* access = call.file_access())
    if (const std::optional<std::string> refusal = access->read_refusal(path, written))
      fail_import(b.span(0), "cannot import " + *refusal, access->allow_hint(path), ErrorKind::Denied);
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status))
    fail_import(
        b.span(0),
        "cannot import '" + written + "': no such file (looked for " + path.lexically_normal().string() + ")",
        "paths are relative to the script that names them", ErrorKind::Input);
  const std::uintmax_t size = fs::is_regular_file(status) ? fs::file_size(path, ec) : 0;
  const auto mtime = fs::last_write_time(path, ec).time_since_epoch().count();
  const CacheKey key{fs::weakly_canonical(path, ec).string(), crease, smooth, size, mtime};
  call.note_input(std::get<0>(key));

  CachedMesh mesh;
  {
    const std::lock_guard<std::mutex> lock(cache_mutex);
    if (const auto it = cache.find(key); it != cache.end()) mesh = it->second;
  }
  if (!mesh.solid) {
    call.budget().check_memory_ahead(b.span(0), static_cast<double>(size) * kEstimatedBytesPerMeshByte,
                                     "mesh read");
    try {
      stdlib::MeshImportOptions options;
      options.crease_angle_deg = crease;
      options.max_faces = call.budget().limits().faces;
      stdlib::ImportedMesh imported = stdlib::import_mesh(path, options);
      imported.solid.smooth_contours = smooth;
      mesh.solid = std::make_shared<const Solid>(std::move(imported.solid));
      mesh.warnings = std::move(imported.warnings);
    } catch (const stdlib::MeshImportError& e) {
      const stdlib::MeshProblem& p = e.problem;
      // A file that exists but cannot be opened is an input problem (exit 66); bad content is the
      // script's (exit 65), like any other bad data it names.
      const bool unreadable =
          p.line == 0 && (p.message.rfind("cannot open", 0) == 0 || p.message.rfind("cannot read", 0) == 0);
      // The importers' face limit is the run's (--limit faces=N): say which option raises it.
      const std::string hint = p.hint.rfind("raise the face limit", 0) == 0
                                   ? "--limit faces=N raises the face limit" + p.hint.substr(20)
                                   : p.hint;
      fail_import(b.span(0), "cannot import '" + written + "': " + problem_text(p, path, written), hint,
                  unreadable ? ErrorKind::Input : ErrorKind::Script);
    }
    const std::lock_guard<std::mutex> lock(cache_mutex);
    cache.emplace(key, mesh);
  }
  call.budget().charge_faces_built(call.site().span, mesh.solid->faces.size());
  for (const stdlib::MeshProblem& w : mesh.warnings) {
    lang::Diagnostic d;
    d.severity = lang::Severity::Warning;
    d.span = b.span(0);
    d.message = "import '" + written + "': " + problem_text(w, path, written);
    d.hint = w.hint;
    call.budget().warn(std::move(d));
  }
  return Value::solid(mesh.solid, fs::path(written).stem().string());
}

const BuiltinEntry kImportBuiltins[] = {
    {"import",
     "import(path, crease: 0, contours: \"edges\")",
     import_,
     "A solid read from a mesh file (OFF, OBJ, STL, Albers' .VER/.SUR), its path relative to the script.",
     {&kImportParams}},
};

}  // namespace

void register_import_builtins(BuiltinTable& table) { table.add_all(kImportBuiltins); }

}  // namespace hlr::runtime
