// The fast mesh readers (FastCursor) against the careful ones: on every text the fast reader takes, the
// careful reader must take it too and read the same RawMesh (vertices, faces, lines and columns), so
// taking the fast path never changes a result or a message. Texts: the common forms, which the fast
// readers must take, and seeded byte mutations of them, which they may take or decline.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "stdlib/mesh_detail.hpp"
#include "tests/support/seeded_rng.hpp"

namespace hlr::stdlib::mesh_detail {
namespace {

using Fast = std::function<bool(std::string_view, RawMesh&)>;
using Careful = std::function<RawMesh(std::string_view)>;

struct Format {
  const char* name;
  Fast fast;
  Careful careful;
  std::vector<std::string> common;  // texts the fast reader must take
};

std::vector<Format> formats() {
  const MeshImportOptions o;
  std::vector<Format> all = {
      {"off",
       [o](std::string_view t, RawMesh& r) { return read_off_fast(t, "m.off", o, r); },
       [o](std::string_view t) { return read_off_careful(t, "m.off", o); },
       {"OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
        "OFF 4 4 0\r\n0.5 -0 1e-3\r\n1.25E2 0 0\r\n0 1 0 0.1 0.2 0.3\r\n0 0 1\r\n3 0 2 1 0.5 0.5 0.5 1\r\n"
        "3 0 1 3\r\n3 0 3 2\r\n3 1 2 3",
        "\xEF\xBB\xBF# a comment\nOFF\n\n# counts\n4\t4 6 # edges\n0 0 0\n  1 0 0\n0 1 0 # top\n0 0 1\n"
        "3 0 2 1\n3 0 1 3\n\n3 0 3 2\n3 1 2 3\n\n"}},
      // OFF read in parts of a few bytes (split at nearly every line end), as large files are read.
      {"off in parts",
       [o](std::string_view t, RawMesh& r) { return read_off_fast(t, "m.off", o, r, 8); },
       [o](std::string_view t) { return read_off_careful(t, "m.off", o); },
       {}},
      {"obj",
       [o](std::string_view t, RawMesh& r) { return read_obj_fast(t, "m.obj", o, r); },
       [o](std::string_view t) { return read_obj_careful(t, "m.obj", o); },
       {"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
        "# exported\no thing\nmtllib a.mtl\nv 0 0 0 1\nv 1 0 0\r\nvt 0 0\nvn 0 0 1\nv 0 1 0\nv 0 0 1\n"
        "usemtl x\ns off\nf 1/1/1 3/1/1 2/1/1\nf 1//1 2//1 4//1\nf -4/1 -1/1 -2/1\nf 2 3 4 # last\n",
        "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"}},
      {"stl",
       [o](std::string_view t, RawMesh& r) { return read_stl_ascii_fast(t, "m.stl", o, r); },
       [o](std::string_view t) { return read_stl_ascii_careful(t, "m.stl", o, false); },
       {"solid cube\nfacet normal 0 0 -1\n outer loop\n  vertex 0 0 0\n  vertex 0 1 0\n  vertex 1 0 0\n"
        " endloop\nendfacet\nfacet normal nan nan nan\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\n"
        "endloop\nendfacet\nendsolid cube\n",
        "solid\r\n  facet normal 0 0 1 outer loop vertex 1 0 0 vertex\t0 1 0\r\n vertex 0 0 1 endloop "
        "endfacet\r\n"
        "endsolid\r\nsolid second\nfacet outer loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 0 0 1\n"
        "endloop endfacet\nendsolid"}},
  };
  all[1].common = all[0].common;
  return all;
}

std::string mutate(const std::string& text, test::Rng& rng) {
  static const std::string alphabet = " \t\r\n#-+.eE0123456789/ofvOFF\xEF";
  std::string s = text;
  const int edits = rng.integer(1, 3);
  for (int k = 0; k < edits && !s.empty(); ++k) {
    const auto at = static_cast<std::size_t>(rng.integer(0, static_cast<int>(s.size()) - 1));
    const char c = alphabet[static_cast<std::size_t>(rng.integer(0, static_cast<int>(alphabet.size()) - 1))];
    switch (rng.integer(0, 2)) {
      case 0:
        s[at] = c;
        break;
      case 1:
        s.insert(s.begin() + static_cast<std::ptrdiff_t>(at), c);
        break;
      default:
        s.erase(at, 1);
        break;
    }
  }
  return s;
}

void expect_same(const Format& f, const std::string& text, bool must_take, int& taken, int& declined) {
  RawMesh fast;
  if (!f.fast(text, fast)) {
    EXPECT_FALSE(must_take) << f.name << " fast reader declined a common form:\n" << text;
    ++declined;
    return;
  }
  ++taken;
  try {
    const RawMesh careful = f.careful(text);
    EXPECT_TRUE(careful == fast) << f.name << " readers differ on:\n" << text;
  } catch (const MeshImportError& e) {
    ADD_FAILURE() << f.name << ": the fast reader took a text the careful one refuses (" << e.what() << "):\n"
                  << text;
  }
}

TEST(FastMeshReaders, TakeTheCommonFormsAndReadThemAsTheCarefulReaders) {
  for (const Format& f : formats()) {
    if (f.common.empty()) continue;
    int taken = 0, declined = 0;
    for (const std::string& text : f.common) expect_same(f, text, true, taken, declined);
    EXPECT_EQ(taken, static_cast<int>(f.common.size()));
  }
}

TEST(FastMeshReaders, MutationsAreDeclinedOrReadAsTheCarefulReadersRead) {
  test::Rng rng(20261202);
  for (const Format& f : formats()) {
    if (f.common.empty()) continue;
    int taken = 0, declined = 0;
    for (int i = 0; i < 3000; ++i) {
      const std::string& base = f.common[static_cast<std::size_t>(i) % f.common.size()];
      expect_same(f, mutate(base, rng), false, taken, declined);
    }
    EXPECT_GT(taken, 100) << f.name;  // both sides of the decision are exercised
    EXPECT_GT(declined, 300) << f.name;
  }
}

}  // namespace
}  // namespace hlr::stdlib::mesh_detail
