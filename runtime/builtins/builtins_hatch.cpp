// hatch(): shading for plotters, lines laid on the faces of solids (core/solid/hatching.hpp). This file
// checks the arguments, bounds the lines before any is laid, and caches what it lays across frames.
#include <cmath>
#include <string>

#include "core/format_number.hpp"
#include "core/limits.hpp"
#include "core/solid/hatching.hpp"
#include "runtime/builtins/builtins.hpp"
#include "runtime/builtins/solid_cache.hpp"

namespace hlr::runtime {
namespace {

constexpr KindSet kNumber = kinds(ValueKind::Number);

// What a hatch line costs until the frame is drawn: its two vertices and edge in the solid, its candidate
// in the engine.
constexpr double kBytesPerHatchLine = 256;

const ParamList kHatchParams = {
    required("object", kinds(ValueKind::Solid, ValueKind::Group, ValueKind::List)),
    required("spacing", kNumber),
    optional("angle", kNumber, Value::number(45)),
    optional("light", kinds(ValueKind::Vector)),
    optional("cross", kinds(ValueKind::Bool), Value::boolean(false)),
    optional("pen", kNumber),
    optional("planes", kinds(ValueKind::Vector))};

// The exact key of a hatching, for the cache.
std::string hatch_key(const HatchSpec& spec, int pen) {
  std::string key = "hatch:";
  put_bits(spec.spacing, key);
  put_bits(spec.angle_deg, key);
  key += spec.light ? 'l' : '-';
  if (spec.light) {
    put_bits(spec.light->x, key);
    put_bits(spec.light->y, key);
    put_bits(spec.light->z, key);
  }
  key += spec.cross ? 'x' : '-';
  key += spec.planes ? 's' : '-';
  if (spec.planes) {
    put_bits(spec.planes->x, key);
    put_bits(spec.planes->y, key);
    put_bits(spec.planes->z, key);
  }
  key += std::to_string(pen);
  return key;
}

// hatch(object, spacing, angle: 45, light: none, cross: false, pen: none, planes: none)
Value hatch_(CallArgs& call) {
  const Bound b = call.bind(kHatchParams);
  HatchSpec spec;
  spec.spacing = b.positive(1);
  spec.angle_deg = b.number(2);
  if (!std::isfinite(spec.angle_deg)) b.fail(2, "must be a finite number of degrees");
  if (b.present(3)) {
    const Vector3 light = b.vector(3);
    if (!(length(light) > 0) || !std::isfinite(length(light)))
      b.fail(3, "must be a direction towards the light, not the zero vector");
    spec.light = light;
  }
  spec.cross = b.boolean(4);
  const int pen = b.present(5) ? b.whole(5, 1, kMaxPen) : 0;  // 0: keep the solid's (its drawing pen)
  if (b.present(6)) {
    if (b.given(2)) b.fail(6, "cannot go with angle: both say which way the lines run; give one of them");
    const Vector3 normal = b.vector(6);
    if (!(length(normal) > 0) || !std::isfinite(length(normal)))
      b.fail(6, "must be the direction the planes are normal to, not the zero vector");
    spec.planes = normal;
  }

  // A solid is hatched in its own coordinates; the members of a group or list in the group's, each moved
  // there first, so that one light and one angle hold for all of them.
  const bool single = b.value(0).is(ValueKind::Solid);
  std::vector<PlacedSolid> members = solids_where_placed(call, b.value(0), b.span(0));

  double lines = 0;
  for (const PlacedSolid& m : members) lines += static_cast<double>(hatch_line_bound(*m.solid, spec));
  if (lines > kMaxHatchLines)
    b.fail(1, "would lay about " + format_for_message(std::round(lines)) + " hatch lines (at most " +
                  format_for_message(kMaxHatchLines) +
                  "): give a wider spacing, in the solid's units like its coordinates");
  call.budget().charge_memory(call.site().span, lines * kBytesPerHatchLine, "hatch lines");

  const std::string key = hatch_key(spec, pen);
  for (PlacedSolid& m : members) {
    const std::shared_ptr<const Solid> source = m.solid;
    m.solid = SolidCache::shared().derived(source, key, [&] {
      Solid out = hatched(*source, spec);
      if (pen > 0) out.hatch_pen = pen;
      return std::make_shared<const Solid>(std::move(out));
    });
  }
  if (single) return Value::solid(members[0].solid, members[0].name);
  return Value::group(std::move(members));
}

const BuiltinEntry kHatchBuiltins[] = {
    {"hatch",
     "hatch(object, spacing, angle: 45, light: none, cross: false, pen: none, planes: none)",
     hatch_,
     "A solid (or group) with parallel hatch lines laid on its faces, spacing apart (or shaded by light), "
     "drawn where visible in the hatch pen.",
     {&kHatchParams}},
};

}  // namespace

void register_hatch_builtins(BuiltinTable& table) { table.add_all(kHatchBuiltins); }

}  // namespace hlr::runtime
