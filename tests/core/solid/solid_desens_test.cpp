// The thesis objects (Desens 1969): the L-shaped block and the aircraft carrier, built from the
// fixture's node and face lists exactly as printed (faces as single loops with doubled edges), checked
// against the thesis's LINES table: order, end points, faces on both sides, concave flags.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/core/solid/solid_test_helpers.hpp"

namespace hlr {
namespace {

using namespace solid_test;

const nlohmann::json& fixtures() {
  static const nlohmann::json data = [] {
    std::ifstream in(HLR_TEST_DATA_DIR "/desens_fixtures.json");
    EXPECT_TRUE(in.good()) << "cannot read " HLR_TEST_DATA_DIR "/desens_fixtures.json";
    return in.good() ? nlohmann::json::parse(in) : nlohmann::json::object();
  }();
  return data;
}

// Vertices "1".."N" in node order (so vertex index = node id − 1); face k has tag k.
SolidBuildResult build_object(const std::string& name, SolidBuildOptions options = {}) {
  const nlohmann::json& object = fixtures().at(name);
  SolidBuilder b(options);
  const auto& nodes = object.at("nodes");
  for (std::size_t id = 1; id <= nodes.size(); ++id) {
    const auto& p = nodes.at(std::to_string(id));
    b.add_vertex(std::to_string(id), {p[0].get<double>(), p[1].get<double>(), p[2].get<double>()},
                 static_cast<std::int64_t>(id));
  }
  std::int64_t tag = 1;
  for (const auto& face : object.at("faces")) {
    std::vector<std::string> loop;
    for (const auto& id : face) loop.push_back(std::to_string(id.get<int>()));
    b.add_face_loop(loop, tag++);
  }
  return b.build();
}

// Edge i of the solid is LINES entry i: low/high node, face traversing low→high (left), the other.
void expect_thesis_lines(const Solid& s, const nlohmann::json& lines) {
  ASSERT_EQ(s.edges.size(), lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const auto& l = lines[i];
    const SolidEdge& e = s.edges[i];
    SCOPED_TRACE("line " + std::to_string(l.at("id").get<int>()));
    EXPECT_EQ(e.v0 + 1, l.at("low").get<unsigned>());
    EXPECT_EQ(e.v1 + 1, l.at("high").get<unsigned>());
    EXPECT_EQ(e.left + 1, l.at("face_fwd").get<int>());
    EXPECT_EQ(e.right + 1, l.at("face_rev").get<int>());
    EXPECT_EQ(e.concave, l.at("concave").get<bool>());
    if (l.at("face_fwd") == l.at("face_rev"))
      EXPECT_EQ(e.kind, EdgeKind::Marking);
    else
      EXPECT_EQ(e.kind, EdgeKind::Feature);
  }
}

TEST(SolidDesens, LBlock) {
  const SolidBuildResult r = build_object("lblock");
  ASSERT_TRUE(r.ok()) << all_messages(r);
  EXPECT_TRUE(r.diagnostics.empty()) << all_messages(r);
  const Solid& s = *r.solid;
  expect_valid_solid(s);
  EXPECT_EQ(s.vertices.size(), 12u);
  EXPECT_EQ(s.faces.size(), 8u);
  EXPECT_TRUE(s.closed);
  EXPECT_EQ(s.edges.size(), 18u);
  ASSERT_EQ(count_concave(s), 1u);
  const SolidEdge* concave = find_edge(s, 6, 9);  // nodes 7–10, the re-entrant edge
  ASSERT_NE(concave, nullptr);
  EXPECT_TRUE(concave->concave);
  EXPECT_NEAR(signed_volume(s), 5 * 10 * 5 + 11 * 3 * 5, 1e-9);
  expect_thesis_lines(s, fixtures().at("lblock").at("lines"));
}

// Thesis data defects, found by the checks:
// * The hull faces 13–16 are warped quadrilaterals (Desens never checked planarity; CCVCVX takes each
//   normal from the first corner). Faces 14 and 15 (the bow) are off by 1.07 ft over 403 ft; no choice
//   of the unconstrained nodes 43/46 fixes that, since edge 39–47 is raked and 43–46 vertical.
// * Face 17 (slab underside) has the hull's top outline as its hole, but that outline (edge 45–48, at
//   v ≈ 62) pokes out past the slab's starboard notch (edges 54–55 at u = 930 and 55–56), by up to
//   12 ft: the hull is wider than the deck there.
// Strictly, the carrier is therefore rejected, naming exactly those faces.
TEST(SolidDesens, CarrierIsRejectedByTheStrictChecks) {
  const SolidBuildResult r = build_object("carrier");
  EXPECT_FALSE(r.ok());
  const auto warped = with_code(r, "non-planar");
  const auto holes = with_code(r, "bad-hole");
  EXPECT_EQ(warped.size() + holes.size(), r.diagnostics.size()) << all_messages(r);
  ASSERT_EQ(warped.size(), 4u) << all_messages(r);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(warped[i]->tag, static_cast<std::int64_t>(13 + i));
    EXPECT_EQ(warped[i]->message.rfind(id("face ", 13 + i) + " is not planar: vertex ", 0), 0u);
  }
  EXPECT_NE(warped[1]->message.find(" lies 1.07248 off the face's mean plane"), std::string::npos) << warped[1]->message;
  ASSERT_EQ(holes.size(), 1u) << all_messages(r);
  EXPECT_EQ(holes[0]->tag, 17);
  EXPECT_EQ(holes[0]->message.rfind("hole 1 of face 17 crosses its outer boundary (edges 45\u201348 and 54\u201355)", 0),
            0u)
      << holes[0]->message;
}

TEST(SolidDesens, Carrier) {
  SolidBuildOptions options;
  options.planarity_tolerance = 3e-3;  // admits the warped hull (2.7e-3 of face size at worst)
  options.allow_crossing_holes = true;  // and face 17's protruding hole
  const SolidBuildResult r = build_object("carrier", options);
  ASSERT_TRUE(r.ok()) << all_messages(r);
  EXPECT_EQ(with_code(r, "non-planar").size(), 4u);
  EXPECT_EQ(with_code(r, "bad-hole").size(), 1u);
  EXPECT_EQ(r.diagnostics.size(), 5u) << all_messages(r);  // in particular, no winding fixes needed
  for (const SolidDiagnostic& d : r.diagnostics) EXPECT_EQ(d.severity, SolidDiagnostic::Severity::Warning);
  const Solid& s = *r.solid;
  expect_valid_solid(s, 1.1);  // the hull's warp
  EXPECT_EQ(s.vertices.size(), 62u);
  EXPECT_EQ(s.faces.size(), 32u);
  EXPECT_TRUE(s.closed);
  EXPECT_EQ(s.edges.size(), 93u);  // the thesis's LINES count, on-face lines included
  EXPECT_EQ(count_concave(s), 18u);
  EXPECT_GT(signed_volume(s), 0);

  // The on-face lines, by thesis line id: the deck's angled-deck chain and spurs, the island bridge
  // 20–21, and the overhang's bridge 37–38.
  std::vector<int> markings;
  for (std::size_t i = 0; i < s.edges.size(); ++i)
    if (s.edges[i].kind == EdgeKind::Marking) markings.push_back(static_cast<int>(i) + 1);
  EXPECT_EQ(markings, (std::vector<int>{9, 10, 11, 12, 13, 14, 15, 21, 79}));

  // Faces given as one loop: deck (island footprint hole), slab underside (hull outline touching the
  // outer ring at node 47), overhang underside (annulus).
  const std::vector<std::pair<int, std::vector<VertexIndex>>> holes = {
      {1, {21, 22, 23, 24}}, {17, {47, 46, 44, 45, 48}}, {18, {38, 35, 28, 27}}};
  for (const auto& [face, nodes] : holes) {
    SCOPED_TRACE(id("face ", face));
    const Face& f = s.faces[static_cast<std::size_t>(face - 1)];
    ASSERT_EQ(f.rings.size(), 2u);
    std::vector<VertexIndex> hole(f.rings[1].vertices.begin(), f.rings[1].vertices.end());
    for (VertexIndex& v : hole) ++v;
    std::sort(hole.begin(), hole.end());
    std::vector<VertexIndex> expected = nodes;
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(hole, expected);
  }
  EXPECT_NEAR(s.planes[0].normal.z, 1, 1e-12);    // deck faces up
  EXPECT_NEAR(s.planes[16].normal.z, -1, 1e-12);  // undersides face down
  EXPECT_NEAR(s.planes[17].normal.z, -1, 1e-12);
  expect_thesis_lines(s, fixtures().at("carrier").at("lines"));
}

}  // namespace
}  // namespace hlr
