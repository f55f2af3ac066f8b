// HLRBRep_PolyAlgo on the solid's own faces. The shape: one planar TopoDS_Face per face of the solid,
// sharing one TopoDS_Edge per solid edge and one TopoDS_Vertex per solid vertex (built directly, so no
// sewing tolerance is involved), in a closed shell and a solid. Each edge the solid classifies Smooth or
// Flat (dihedral angle below the crease angle) is marked G1 between its two faces by
// BRepLib::EncodeRegularity with the crease angle as its tolerance, so OCCT calls it a smooth (Rg1)
// edge; every other edge stays C0, a sharp edge. BRepMesh then triangulates the planar faces (exactly:
// no deflection is involved), which HLRBRep_PolyAlgo needs.
#include "bench/peers/occt_peer.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <HLRAlgo_BiPoint.hxx>
#include <HLRAlgo_EdgeIterator.hxx>
#include <HLRAlgo_EdgeStatus.hxx>
#include <HLRAlgo_Projector.hxx>
#include <HLRBRep_PolyAlgo.hxx>
#include <HLRBRep_PolyHLRToShape.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Builder.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <gp_Ax2.hxx>
#include <gp_Pln.hxx>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "core/tolerance.hpp"

namespace hlr::peers {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

gp_Pnt to_gp(Point3 p) { return {p.x, p.y, p.z}; }

TopoDS_Shape build_shape(const Solid& solid) {
  // (TopoDS_Builder, not BRep_Builder: Debian's libocct-foundation-dev 7.6.3 lacks
  // NCollection_AliasedArray.hxx, which BRep_Builder.hxx and BRep_Tool.hxx include.)
  TopoDS_Builder b;
  std::vector<TopoDS_Vertex> vertices(solid.vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i)
    vertices[i] = BRepBuilderAPI_MakeVertex(to_gp(solid.vertices[i])).Vertex();

  std::vector<TopoDS_Edge> edges(solid.edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const SolidEdge& e = solid.edges[i];
    if (e.kind == EdgeKind::Marking || e.kind == EdgeKind::Free) continue;  // not in the scenes compared
    edges[i] = BRepBuilderAPI_MakeEdge(vertices[e.v0], vertices[e.v1]).Edge();
  }

  std::vector<TopoDS_Face> faces(solid.faces.size());
  TopoDS_Shell shell;
  b.MakeShell(shell);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Plane& plane = solid.planes[f];
    const gp_Pln pln(gp_Pnt(-plane.offset * plane.normal.x, -plane.offset * plane.normal.y,
                            -plane.offset * plane.normal.z),
                     gp_Dir(plane.normal.x, plane.normal.y, plane.normal.z));
    std::vector<TopoDS_Wire> wires;
    for (const Ring& ring : solid.faces[f].rings) {
      TopoDS_Wire w;
      b.MakeWire(w);
      for (std::size_t i = 0; i < ring.vertices.size(); ++i) {
        const std::uint32_t ei = ring.edges[i];
        if (ei == kNoEdge) throw std::runtime_error("occt peer: a ring edge is not linked");
        const bool forward = solid.edges[ei].v0 == ring.vertices[i];
        b.Add(w, edges[ei].Oriented(forward ? TopAbs_FORWARD : TopAbs_REVERSED));
      }
      w.Closed(true);
      wires.push_back(w);
    }
    BRepBuilderAPI_MakeFace make(pln, wires.front(), true);
    for (std::size_t r = 1; r < wires.size(); ++r) make.Add(wires[r]);
    if (!make.IsDone()) throw std::runtime_error("occt peer: BRepBuilderAPI_MakeFace failed");
    faces[f] = make.Face();
    b.Add(shell, faces[f]);
  }
  // Only the edges we call Smooth or Flat are offered to EncodeRegularity, with the crease angle widened
  // by our coplanar angle as its angular tolerance: Flat edges bend by less than the latter, Smooth ones
  // by at most the former, and it marks G1 where the faces' normals differ by less.
  const double tol_ang = solid.crease_angle_deg * std::numbers::pi / 180 + Tolerance::kCoplanarAngle;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const SolidEdge& e = solid.edges[i];
    if ((e.kind == EdgeKind::Smooth || e.kind == EdgeKind::Flat) && e.left != kNoFace && e.right != kNoFace)
      BRepLib::EncodeRegularity(edges[i], faces[static_cast<std::size_t>(e.left)],
                                faces[static_cast<std::size_t>(e.right)], tol_ang);
  }
  shell.Closed(solid.closed);
  TopoDS_Shape shape = shell;
  if (solid.closed) {
    TopoDS_Solid s;
    b.MakeSolid(s);
    b.Add(s, shell);
    shape = s;
  }
  // Planar faces bounded by straight edges: the triangulation is exact whatever the deflection, so any
  // positive one does (our planarity tolerance, relative to the faces' size).
  BRepMesh_IncrementalMesh mesh(shape, Tolerance::kPlanarity, true, 0.5, false);
  if (!mesh.IsDone()) throw std::runtime_error("occt peer: BRepMesh failed");
  return shape;
}

// OCCT's projector for our camera: local axes X = right, Y = up, Z = −forward (right-handed), the
// eye at Z = focus on the Z axis. OCCT's perspective is X·focus/(focus − Z), ours focal·x/depth with
// depth = focus − Z, so our picture = (focal/focus)·OCCT's picture + offset.
struct Projection {
  HLRAlgo_Projector projector;
  double scale = 1;  // OCCT picture → ours
  Vector2 shift{};   // added after scaling
};

Projection make_projection(const Solid& solid, const Camera& camera) {
  const auto& m = camera.viewFromWorld.m;
  const Vector3 right{m[0][0], m[0][1], m[0][2]}, up{m[1][0], m[1][1], m[1][2]},
      fwd{m[2][0], m[2][1], m[2][2]};
  const double tol = Tolerance::kRelative;
  if (std::abs(dot(right, right) - 1) > tol || std::abs(dot(up, up) - 1) > tol ||
      std::abs(dot(fwd, fwd) - 1) > tol || std::abs(dot(right, up)) > tol ||
      std::abs(dot(right, fwd)) > tol || std::abs(dot(up, fwd)) > tol || dot(cross(right, up), fwd) > 0)
    throw std::runtime_error("occt peer: the camera's view axes are not a right-handed orthonormal frame");
  // Focus: the depth of the solid's centre, so OCCT's picture plane passes through the object.
  Point3 lo = solid.vertices.front(), hi = lo;
  for (Point3 p : solid.vertices) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const Point3 centre{0.5 * (lo.x + hi.x), 0.5 * (lo.y + hi.y), 0.5 * (lo.z + hi.z)};
  Projection p;
  if (camera.projection == hlr::Projection::Perspective) {
    const Point3 eye = camera.eye_world();
    const double focus = camera.view(centre).z;
    if (!(focus > 0)) throw std::runtime_error("occt peer: the solid's centre is behind the eye");
    const Point3 origin = eye + focus * fwd;
    p.projector = HLRAlgo_Projector(
        gp_Ax2(to_gp(origin), gp_Dir(-fwd.x, -fwd.y, -fwd.z), gp_Dir(right.x, right.y, right.z)), focus);
    p.scale = camera.focal / focus;
    p.shift = camera.offset;
  } else {
    const Point3 v = camera.view(centre);
    const Point3 origin = centre;  // view (x, y) of the origin is added back
    p.projector = HLRAlgo_Projector(
        gp_Ax2(to_gp(origin), gp_Dir(-fwd.x, -fwd.y, -fwd.z), gp_Dir(right.x, right.y, right.z)));
    p.scale = camera.focal;
    p.shift = {camera.offset.x + camera.focal * v.x, camera.offset.y + camera.focal * v.y};
  }
  return p;
}

// Sum of the 2-D lengths of a compound's edges (straight segments from the polygonal algorithm). Note
// that HLRBRep_PolyHLRToShape places the pieces in the projector's frame without the perspective
// division (it applies the visibility parameters to the transformed 3-D end points): under a
// perspective projector its compounds are not the picture the hiding was done in.
double picture_length(const TopoDS_Shape& compound, double scale, std::size_t& count) {
  double length = 0;
  if (compound.IsNull()) return 0;
  for (TopExp_Explorer ex(compound, TopAbs_EDGE); ex.More(); ex.Next()) {
    const BRepAdaptor_Curve c(TopoDS::Edge(ex.Current()));
    const gp_Pnt a = c.Value(c.FirstParameter()), z = c.Value(c.LastParameter());
    length += scale * std::hypot(z.X() - a.X(), z.Y() - a.Y());
    ++count;
  }
  return length;
}

}  // namespace

// The polyhedral algorithm with the shape and projector loaded and Update() run (the hiding itself waits
// for Hide()); tol_angular ≤ 0 keeps OCCT's default.
Handle(HLRBRep_PolyAlgo) updated_algo(const TopoDS_Shape& shape, const Projection& proj, double tol_angular) {
  Handle(HLRBRep_PolyAlgo) algo = new HLRBRep_PolyAlgo();
  algo->Load(shape);
  algo->Projector(proj.projector);
  if (tol_angular > 0) algo->TolAngular(tol_angular);
  algo->Update();
  return algo;
}

OcctResult run_occt(const Solid& solid, const Camera& camera, int runs, double budget_s, bool to_shape,
                    double tol_angular) {
  OcctResult r;
  auto t0 = std::chrono::steady_clock::now();
  const TopoDS_Shape shape = build_shape(solid);
  r.build_s = seconds_since(t0);
  const Projection proj = make_projection(solid, camera);

  std::vector<double> hide_times;
  double spent = 0;
  for (int run = 0; run < std::max(1, runs) && spent < budget_s; ++run) {
    t0 = std::chrono::steady_clock::now();
    Handle(HLRBRep_PolyAlgo) algo = updated_algo(shape, proj, tol_angular);
    // Hide() hides each edge when it is asked for (HLRAlgo_PolyAlgo works lazily), so the loop is
    // part of the hiding. The visibility parameters run along the projected segment PntP1 → PntP2
    // (perspective already divided), so the pieces are measured there.
    double compared = 0, smooth = 0;
    std::size_t pieces = 0;
    TopoDS_Shape edge_shape;
    Standard_Boolean reg1 = false, regn = false, outl = false, intl = false;
    HLRAlgo_EdgeStatus status;
    HLRAlgo_EdgeIterator it;
    for (algo->InitHide(); algo->MoreHide(); algo->NextHide()) {
      const HLRAlgo_BiPoint::PointsT& points = algo->Hide(status, edge_shape, reg1, regn, outl, intl);
      const gp_XY a = points.PntP12D(), d = points.PntP22D() - a;
      const double span = proj.scale * d.Modulus();
      double visible = 0;
      Standard_Real start = 0, end = 0;
      Standard_ShortReal tol_start = 0, tol_end = 0;
      for (it.InitVisible(status); it.MoreVisible(); it.NextVisible()) {
        it.Visible(start, tol_start, end, tol_end);
        visible += (end - start) * span;
        ++pieces;
      }
      // HLRBRep_PolyHLRToShape's classes: VCompound = !(intl || (reg1 && !outl)), OutLineVCompound =
      // intl, Rg1LineVCompound = reg1 && !regn && !outl.
      if (intl || !(reg1 && !outl))
        compared += visible;
      else if (reg1 && !regn)
        smooth += visible;
    }
    hide_times.push_back(seconds_since(t0));
    spent += hide_times.back();
    r.visible_length = compared;
    r.smooth_visible_length = smooth;
    r.visible_pieces = pieces;
  }
  r.runs = static_cast<int>(hide_times.size());
  r.hide_s = median(hide_times);

  if (to_shape) {
    t0 = std::chrono::steady_clock::now();
    Handle(HLRBRep_PolyAlgo) algo = updated_algo(shape, proj, tol_angular);
    HLRBRep_PolyHLRToShape extract;
    extract.Update(algo);
    const TopoDS_Shape sharp = extract.VCompound(), outline = extract.OutLineVCompound();
    r.to_shape_s = seconds_since(t0);
    std::size_t edges = 0;
    r.to_shape_length = picture_length(sharp, proj.scale, edges) + picture_length(outline, proj.scale, edges);
  }
  return r;
}

}  // namespace hlr::peers
