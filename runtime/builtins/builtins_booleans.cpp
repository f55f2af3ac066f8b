// union(), difference(), intersection(): booleans of solids (stdlib/booleans.hpp). Each argument is a solid,
// a group or a list of them (placed solids are taken where they are placed) and stands for the union of
// what it holds; the result is a solid in those coordinates, cached across frames like a generator's.
#include <cmath>
#include <string>

#include "core/format_number.hpp"
#include "core/geometry/box3.hpp"
#include "core/limits.hpp"
#include "core/solid/hatching.hpp"
#include "core/tolerance.hpp"
#include "runtime/builtins/builtins.hpp"
#include "runtime/builtins/solid_cache.hpp"
#include "runtime/values/placement.hpp"
#include "stdlib/booleans.hpp"
#include "stdlib/generators.hpp"

namespace hlr::runtime {
namespace {

using stdlib::BooleanOp;

Value boolean_of(CallArgs& call, BooleanOp op) {
  const std::string name = call.site().function;
  for (const Arg& a : call.args())
    if (!a.label.empty())
      call.fail(a.label_span, name + "() takes no named arguments: give the solids in order");
  if (call.args().empty()) call.fail_call(name + "() needs at least one solid");

  // The operands in order, and which argument each came from (for the message that names it).
  std::vector<std::shared_ptr<const Solid>> operands;
  std::vector<std::size_t> from;
  std::vector<std::string> names;
  std::size_t faces = 0;
  for (std::size_t i = 0; i < call.args().size(); ++i) {
    const Arg& arg = call.args()[i];
    if (!is_drawable(arg.value))
      call.fail(arg.span, "bad argument " + std::to_string(i + 1) + " to " + name +
                              "(): expected a solid, a group or a list of them, got " +
                              kind_with_article(arg.value.kind()));
    for (PlacedSolid& m : solids_where_placed(call, arg.value, arg.span)) {
      faces += m.solid->faces.size();
      operands.push_back(std::move(m.solid));
      from.push_back(i);
      names.push_back(m.name);
    }
  }
  if (operands.empty()) call.fail_call(name + "() needs at least one solid; the lists given are empty");
  // The result's faces are not known before it is made; the operands' (cut into a few pieces each) bound
  // what a frame may build.
  call.budget().charge_faces_built(call.site().span, 2 * faces);

  // The key: the operation, each operand's identity and the argument it belongs to. The cache entry keeps
  // every operand alive (an aliasing pointer to the first, owning them all), so no key can name a solid
  // that has gone and whose address was taken again.
  std::string key = std::to_string(static_cast<int>(op)) + ':';
  for (std::size_t k = 0; k < operands.size(); ++k)
    key += std::to_string(reinterpret_cast<std::uintptr_t>(operands[k].get())) + '@' +
           std::to_string(from[k]) + ',';
  auto keep = std::make_shared<std::vector<std::shared_ptr<const Solid>>>(operands);
  const std::shared_ptr<const Solid> holder(keep, operands[0].get());

  try {
    const std::shared_ptr<const Solid> result = SolidCache::shared().derived(holder, "boolean:" + key, [&] {
      std::vector<const Solid*> all;
      for (const auto& o : operands) all.push_back(o.get());
      if (op == BooleanOp::Union || call.args().size() == 1)
        return std::make_shared<const Solid>(stdlib::boolean_solid(BooleanOp::Union, all));
      // One part per argument: its solid, or the union of its solids.
      std::vector<Solid> unions;
      unions.reserve(call.args().size());
      std::vector<const Solid*> parts;
      std::vector<std::size_t> first;  // the operand each part starts at
      for (std::size_t k = 0; k < operands.size();) {
        std::size_t end = k;
        while (end < operands.size() && from[end] == from[k]) ++end;
        first.push_back(k);
        if (end - k == 1) {
          parts.push_back(all[k]);
        } else {
          try {
            unions.push_back(stdlib::boolean_solid(BooleanOp::Union, {all.begin() + k, all.begin() + end}));
          } catch (const stdlib::BooleanOperandError& e) {
            throw stdlib::BooleanOperandError(k + e.operand, e.what());
          }
          parts.push_back(&unions.back());
        }
        k = end;
      }
      try {
        return std::make_shared<const Solid>(stdlib::boolean_solid(op, parts));
      } catch (const stdlib::BooleanOperandError& e) {
        throw stdlib::BooleanOperandError(first[e.operand], e.what());
      }
    });
    return Value::solid(result, name);
  } catch (const stdlib::BooleanOperandError& e) {
    const std::size_t arg = from[e.operand];
    call.fail(call.args()[arg].span, "bad argument " + std::to_string(arg + 1) + " to " + name +
                                         "(): " + names[e.operand] + " " + e.what());
  } catch (const std::runtime_error& e) {
    call.fail_call(name + "(): " + e.what());
  }
}

constexpr KindSet kNumber = kinds(ValueKind::Number);

const ParamList kSectionParams = {
    required("object", kinds(ValueKind::Solid, ValueKind::Group, ValueKind::List)),
    required("point", kinds(ValueKind::Vector)),
    required("normal", kinds(ValueKind::Vector)),
    optional("spacing", kNumber),
    optional("angle", kNumber, Value::number(45)),
    optional("pen", kNumber)};

// section(object, point, normal, spacing: none, angle: 45, pen: none): the solid cut by the plane through
// `point` normal to `normal`, the part the normal points into removed (the side towards the viewer of a
// section view), the cut faces hatched — `spacing` apart (a fortieth of the object's size by default), at
// `angle` — in the hatch pen `pen`. The cut is an exact intersection with a half-space (a box far larger
// than the object, one face on the plane); only faces lying in the plane are hatched.
Value section_(CallArgs& call) {
  const Bound b = call.bind(kSectionParams);
  const Vector3 point = b.vector(1), normal = b.vector(2);
  if (!std::isfinite(length(to_vector(Point3{point.x, point.y, point.z}))))
    b.fail(1, "must be a finite point");
  if (!(length(normal) > 0) || !std::isfinite(length(normal)))
    b.fail(2, "must be the direction the cut faces, towards the part removed; not the zero vector");
  const double angle = b.number(4);
  if (!std::isfinite(angle)) b.fail(4, "must be a finite number of degrees");
  const int pen = b.present(5) ? b.whole(5, 1, kMaxPen) : 0;
  std::vector<PlacedSolid> members = solids_where_placed(call, b.value(0), b.span(0));
  if (members.empty()) b.fail(0, "holds no solid to cut");
  Box3 bounds;
  std::size_t faces = 0;
  for (const PlacedSolid& m : members) {
    faces += m.solid->faces.size();
    for (const Point3& v : m.solid->vertices) bounds.include(v);
  }
  const Point3 p{point.x, point.y, point.z};
  const double size = distance(bounds.lo, bounds.hi);
  const double spacing = b.present(3) ? b.positive(3) : size / 40;
  call.budget().charge_faces_built(call.site().span, 2 * faces + 6);

  // The half-space kept, as a box: x = p + a·t1 + b·t2 + c·n for |a|, |b| ≤ L and −2L ≤ c ≤ 0.
  const Vector3 n = normalize(normal);
  const Vector3 t1 = normalize(std::abs(n.x) < 0.9 ? cross(n, Vector3{1, 0, 0}) : cross(n, Vector3{0, 1, 0}));
  const Vector3 t2 = cross(n, t1);
  const Point3 mid{0.5 * (bounds.lo.x + bounds.hi.x), 0.5 * (bounds.lo.y + bounds.hi.y),
                   0.5 * (bounds.lo.z + bounds.hi.z)};
  const double big = 4 * (size + distance(p, mid)) + 1;
  const Solid half = stdlib::box({-big, -big, -2 * big}, {big, big, 0})
                         .transformed(Affine3::from_rows({t1.x, t2.x, n.x}, {t1.y, t2.y, n.y},
                                                         {t1.z, t2.z, n.z}, to_vector(p)));

  std::string key = "section:";
  for (const double x : {p.x, p.y, p.z, n.x, n.y, n.z, spacing, angle}) put_bits(x, key);
  key += std::to_string(pen) + ':';
  for (const PlacedSolid& m : members)
    key += std::to_string(reinterpret_cast<std::uintptr_t>(m.solid.get())) + ',';
  auto keep = std::make_shared<std::vector<PlacedSolid>>(members);
  const std::shared_ptr<const Solid> holder(keep, members[0].solid.get());
  try {
    const std::shared_ptr<const Solid> result = SolidCache::shared().derived(holder, key, [&] {
      std::vector<const Solid*> all;
      for (const PlacedSolid& m : members) all.push_back(m.solid.get());
      const Solid whole = all.size() == 1 ? *all[0] : stdlib::boolean_solid(BooleanOp::Union, all);
      const Solid cut = stdlib::boolean_solid(BooleanOp::Intersection, {&whole, &half});
      HatchSpec spec;
      spec.spacing = spacing;
      spec.angle_deg = angle;
      spec.only_in_plane = Plane{n, -dot(n, to_vector(p))};
      spec.in_plane_tolerance = 16 * Tolerance::for_extent(size + distance(p, Point3{0, 0, 0})).length;
      if (static_cast<double>(hatch_line_bound(cut, spec)) > kMaxHatchLines)
        throw std::runtime_error("the cut faces would take more than " + format_for_message(kMaxHatchLines) +
                                 " hatch lines: give a wider spacing:");
      Solid out = hatched(cut, spec);
      if (pen > 0) out.hatch_pen = pen;
      return std::make_shared<const Solid>(std::move(out));
    });
    return Value::solid(result, "section");
  } catch (const stdlib::BooleanOperandError& e) {
    b.fail(0, members[std::min(e.operand, members.size() - 1)].name + " " + e.what());
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    call.fail_call(what.starts_with("the result is empty")
                       ? "section(): nothing of the object lies behind the plane"
                       : "section(): " + what);
  }
}

Value union_(CallArgs& call) { return boolean_of(call, BooleanOp::Union); }
Value difference_(CallArgs& call) { return boolean_of(call, BooleanOp::Difference); }
Value intersection_(CallArgs& call) { return boolean_of(call, BooleanOp::Intersection); }

const BuiltinEntry kBooleanBuiltins[] = {
    {"union",
     "union(a, b, ...)  (solids, groups or lists of them)",
     union_,
     "The solid that all the solids given fill together, exactly (CGAL's corefinement).",
     {}},
    {"difference",
     "difference(a, b, ...)  (solids, groups or lists of them)",
     difference_,
     "The first solid (or the union of the first group) with all the others cut away, exactly.",
     {}},
    {"intersection",
     "intersection(a, b, ...)  (solids, groups or lists of them)",
     intersection_,
     "The solid all the arguments have in common (each argument the union of its solids), exactly.",
     {}},
    {"section",
     "section(object, point, normal, spacing: none, angle: 45, pen: none)",
     section_,
     "The object cut by the plane through point: the part the normal points into removed, the cut faces "
     "hatched (spacing apart, a fortieth of its size by default) in the hatch pen.",
     {&kSectionParams}},
};

}  // namespace

void register_boolean_builtins(BuiltinTable& table) { table.add_all(kBooleanBuiltins); }

}  // namespace hlr::runtime
