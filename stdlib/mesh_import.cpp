// import_mesh: reads the file (reporting the system's reason when it cannot), picks the parser by the
// extension and, for Albers' pairs, finds the partner file beside it.
#include "stdlib/mesh_import.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <vector>

#include "core/first_touch.hpp"
#include "core/parallel.hpp"
#include "core/release_memory.hpp"
#include "stdlib/mesh_detail.hpp"

namespace hlr::stdlib {

namespace fs = std::filesystem;
using mesh_detail::fail;

std::string MeshProblem::to_string() const {
  std::string s = file;
  if (line > 0) {
    s += ":" + std::to_string(line);
    if (column > 0) s += ":" + std::to_string(column);
  }
  s += ": " + message;
  if (!hint.empty()) s += "; hint: " + hint;
  return s;
}

MeshImportError::MeshImportError(MeshProblem p) : std::runtime_error(p.to_string()), problem(std::move(p)) {}

// Its pages are faulted in on every core first: the 10⁶-triangle torus's 37 MB took 35 ms on one core.
std::optional<std::string> mesh_detail::read_in_parts(int fd, std::size_t size) {
  constexpr std::size_t kPartBytes = std::size_t{4} << 20;
  std::string data;
  data.reserve(size);
  touch_pages(data.data(), size, 0);
  data.resize(size);
  const std::size_t parts = (size + kPartBytes - 1) / kPartBytes;
  std::vector<char> complete(parts, 0);
  parallel_chunks(parts, 0, [&](std::size_t k) {
    std::size_t at = k * kPartBytes;
    const std::size_t end = std::min(size, at + kPartBytes);
    while (at < end) {
      const ssize_t got = ::pread(fd, data.data() + at, end - at, static_cast<off_t>(at));
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) return;  // an error, or the file is shorter now
      at += static_cast<std::size_t>(got);
    }
    complete[k] = 1;
  });
  char past = 0;
  if (std::find(complete.begin(), complete.end(), 0) != complete.end() ||
      ::pread(fd, &past, 1, static_cast<off_t>(size)) != 0)
    return std::nullopt;  // longer now, or unreadable there
  return data;
}

namespace {

std::string lower(std::string s) {
  for (char& c : s)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return s;
}

// The whole file in one buffer sized from the file's size up front: no growing copies of a large mesh.
// (Not mapped: a file truncated while mapped would kill the process with SIGBUS.) The size is checked
// against the limit first: a sparse file, or one in /proc, may claim terabytes it has not got.
std::string read_file(const fs::path& path, const std::string& name, std::uint64_t max_bytes) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (fs::exists(st) && !fs::is_regular_file(st))
    fail(name, 0, 0,
         fs::is_directory(st) ? "cannot read the file: it is a directory"
                              : "cannot read the file: not a regular file",
         "name a mesh file");
  errno = 0;
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file)
    fail(name, 0, 0, std::string("cannot open the file: ") + std::strerror(errno),
         "check the path and permissions");
  const std::uintmax_t expected = fs::file_size(path, ec);
  const auto too_large = [&](const std::string& size) {
    fail(name, 0, 0, "the file has " + size + " bytes, more than the limit of " + std::to_string(max_bytes),
         "simplify the mesh");
  };
  if (!ec && expected > max_bytes) too_large(std::to_string(expected));  // before any allocation
  constexpr std::uintmax_t kReadInPartsFrom = std::uintmax_t{16} << 20;
  if (!ec && expected >= kReadInPartsFrom)
    if (std::optional<std::string> whole =
            mesh_detail::read_in_parts(::fileno(file.get()), static_cast<std::size_t>(expected)))
      return std::move(*whole);
  std::string data;
  // One more byte than expected, so that a read reaching it shows the file grew meanwhile.
  data.resize(ec ? std::size_t{1} << 16 : static_cast<std::size_t>(expected) + 1);
  std::size_t size = 0;
  for (;;) {
    size += std::fread(data.data() + size, 1, data.size() - size, file.get());
    if (size > max_bytes) too_large("at least " + std::to_string(size));  // grew, or its size was unknown
    if (size < data.size()) break;
    data.resize(static_cast<std::size_t>(std::min<std::uint64_t>(2 * data.size(), max_bytes + 1)));
  }
  if (std::ferror(file.get()))
    fail(name, 0, 0, std::string("cannot read the file: ") + std::strerror(errno),
         "check the file and the disk");
  data.resize(size);
  return data;
}

// The file beside `path` with the same stem and extension `want` (lower case, e.g. ".sur") in any case:
// first the same stem exactly, then the stem in any case (DOS names copied to other systems).
std::optional<fs::path> find_partner(const fs::path& path, const std::string& want) {
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  const std::string stem = path.stem().string();
  std::optional<fs::path> loose;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::path candidate = it->path();
    if (lower(candidate.extension().string()) != want) continue;
    const std::string s = candidate.stem().string();
    if (s == stem) return path.has_parent_path() ? candidate : candidate.filename();
    if (!loose && lower(s) == lower(stem)) loose = path.has_parent_path() ? candidate : candidate.filename();
  }
  return loose;
}

}  // namespace

ImportedMesh import_mesh(const fs::path& path, const MeshImportOptions& options) {
  const std::string name = path.string();
  const std::string ext = lower(path.extension().string());
  // The text is let go once read: the solid is built without it.
  auto parsed =
      [&](mesh_detail::RawMesh (*read)(std::string_view, const std::string&, const MeshImportOptions&)) {
        std::string text = read_file(path, name, options.max_file_bytes);
        mesh_detail::RawMesh raw = read(text, name, options);
        release(text);
        return mesh_detail::build_mesh(std::move(raw), options);
      };
  if (ext == ".off") return parsed(&mesh_detail::read_off);
  if (ext == ".obj") return parsed(&mesh_detail::read_obj);
  if (ext == ".stl") return parsed(&mesh_detail::read_stl);
  if (ext == ".ver" || ext == ".sur") {
    const bool given_ver = ext == ".ver";
    const std::string other = given_ver ? ".sur" : ".ver";
    const std::string given_text = read_file(path, name, options.max_file_bytes);
    const std::optional<fs::path> partner = find_partner(path, other);
    if (!partner) {
      std::string upper = other;
      for (char& c : upper)
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
      fail(name, 0, 0,
           std::string("missing ") + (given_ver ? "surface" : "vertex") + " file: no " +
               path.stem().string() + upper + " beside " + path.filename().string(),
           "Albers' objects are a pair of files with the same name: NAME.VER (vertices) and NAME.SUR "
           "(surfaces)");
    }
    const std::string partner_name = partner->string();
    const std::string partner_text = read_file(*partner, partner_name, options.max_file_bytes);
    return given_ver ? import_albers(given_text, partner_text, name, partner_name, options)
                     : import_albers(partner_text, given_text, partner_name, name, options);
  }
  fail(name, 0, 0,
       ext.empty() ? "the file name has no extension" : "unknown mesh format " + mesh_detail::quoted(ext),
       "import reads .off, .obj, .stl and Albers' .ver/.sur files");
}

}  // namespace hlr::stdlib
