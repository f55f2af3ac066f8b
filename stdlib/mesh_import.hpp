// Mesh import for `import("file")`: OFF, OBJ, STL (ASCII and binary) and Albers' .VER/.SUR pairs become
// validated Solids. Messy but usable data is repaired with a warning: vertices at exactly the same
// position are merged, a vertex repeated in a row is dropped, faces with fewer than 3 distinct vertices,
// zero area or the same vertex cycle as an earlier face are dropped, non-planar polygons are triangulated
// (fan when convex, ear clipping otherwise), inconsistent or inside-out winding is reversed, unused
// vertices are left out. Malformed or invalid data throws MeshImportError naming the file, line and
// column (builder errors such as an edge on 3 faces or two nearly coincident vertices name the file's
// face or vertex and its line). Nothing is allocated from a count the file claims before the data
// backing it has been seen, so a lying header cannot exhaust memory.
//
// Accepted formats (extension, case-insensitive):
//  .off  [ST][C][N][n]OFF header (optional; nOFF needs dimension 3; 4OFF and binary OFF are refused),
//        '#' comments anywhere, blank lines, counts "V F [E]" on the header line or the next, one vertex
//        per line (x y z, then any per-vertex extras: normals, colour, texture), one face per line
//        ("n i1 .. in", 0-based indices, then at most 4 colour values).
//  .obj  v (x y z, extras ignored), f and l with "i", "i/t", "i//n", "i/t/n" (1-based, negative = relative
//        to the vertices so far, forward references allowed), faces of any size; l polylines become lines
//        (markings on a face, else free lines); vt vn vp o g s usemtl mtllib p and other attributes ignored;
//        free-form geometry ignored with a warning.
//  .stl  binary when the size is exactly 84 + 50·n for the count n at byte 80 (even if the header starts
//        with "solid"), else ASCII "solid … facet [normal …] outer loop vertex ×≥3 endloop endfacet …
//        endsolid" (several solids allowed, keywords case-insensitive). Vertices are welded by exact
//        coordinate equality; facet normals are ignored (the winding decides).
//  .ver  Albers (1988) App. D: NAME.VER holds one vertex per line, exactly three reals "x y z" (record i
//        is vertex i, 1-based); NAME.SUR (same stem beside it, extension in any case) holds one surface per
//        line: the edge count n, then n+1 vertex numbers listing the loop closed by repeating the first
//        ("03 01 04 02 01"; leading zeros allowed). Whitespace is blanks or tabs, blank lines are skipped,
//        CR LF line ends and a DOS end-of-file mark (Ctrl-Z) are accepted. A loop that runs along an edge
//        in both directions is a face with a hole, the bridge drawn as a line on it (SolidBuilder's
//        face loops); such faces are not triangulated. Importing the .SUR finds the .VER.
//
// Vertex numbers in messages are the file's own (0-based for OFF, 1-based otherwise; STL vertices are
// numbered after welding); faces are numbered 1-based in file order ("face 3", "facet 3", "triangle 3",
// "surface 3").
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/solid/solid.hpp"

namespace hlr::stdlib {

struct MeshImportOptions {
  double crease_angle_deg = 0;         // passed to the solid builder: edges below it are Smooth
  std::size_t max_faces = 10'000'000;  // faces in the file (and after triangulation) beyond this are an error
  // import_mesh: a larger file is an error before anything is read (10 million faces take about 0.5 GB as
  // binary STL, 1 GB as text). A sparse or /proc file may claim any size; it is never allocated.
  std::uint64_t max_file_bytes = std::uint64_t{4} << 30;
};

struct MeshProblem {
  std::string file;
  int line = 0;    // 1-based; 0 = the whole file (binary STL: the byte offset is in the message)
  int column = 0;  // 1-based byte column; 0 = unknown
  std::string message;
  std::string hint;  // what to do about it (may be empty)
  bool operator==(const MeshProblem&) const = default;
  // "file:line:column: message; hint: hint" (parts that are 0 or empty are left out).
  std::string to_string() const;
};

struct MeshImportError : std::runtime_error {
  explicit MeshImportError(MeshProblem p);
  MeshProblem problem;
};

struct ImportedMesh {
  Solid solid;
  std::vector<MeshProblem> warnings;  // repairs made, in the order found (at most 10 per kind, then a count)
};

// Reads `path` and dispatches on its extension. Throws MeshImportError (unreadable file with the errno
// text, unknown extension, missing .SUR/.VER partner, and everything the parsers throw).
ImportedMesh import_mesh(const std::filesystem::path& path, const MeshImportOptions& options = {});

// Parsers of in-memory data; `name` is the file name used in problems.
ImportedMesh import_off(std::string_view text, const std::string& name,
                        const MeshImportOptions& options = {});
ImportedMesh import_obj(std::string_view text, const std::string& name,
                        const MeshImportOptions& options = {});
ImportedMesh import_stl(std::string_view bytes, const std::string& name,
                        const MeshImportOptions& options = {});
ImportedMesh import_albers(std::string_view ver_text, std::string_view sur_text, const std::string& ver_name,
                           const std::string& sur_name, const MeshImportOptions& options = {});

}  // namespace hlr::stdlib
