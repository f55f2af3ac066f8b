// Timelines (core/animation): ease(name, x), track(keys, time:, ease:, spline:) — keyframes evaluated at
// the frame being drawn unless `time:` says otherwise —, spline(points, u, kind:) and the camera that flies
// along a path, follow(path, t, up:, bank:, fov:, aspect:, kind:). Numbers and vectors alike.
#include <string>

#include "core/animation/keyframe_track.hpp"
#include "core/camera/follow_camera.hpp"
#include "runtime/base/did_you_mean.hpp"
#include "runtime/builtins/builtins.hpp"

namespace hlr::runtime {
namespace {

constexpr KindSet kNumber = kinds(ValueKind::Number);
constexpr KindSet kVector = kinds(ValueKind::Vector);
constexpr KindSet kString = kinds(ValueKind::String);
constexpr KindSet kNumberOrVector = kinds(ValueKind::Number, ValueKind::Vector);

std::string easing_list() {
  std::string out;
  for (std::string_view n : easing_names()) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

Easing easing_arg(const Bound& b, std::size_t i) {
  const std::string name = b.value(i).as_string();
  if (const std::optional<Easing> e = easing_named(name)) return *e;
  const std::string guess =
      did_you_mean(name, std::vector<std::string>(easing_names().begin(), easing_names().end()));
  b.fail(i, "unknown easing \"" + name + "\"" + (guess.empty() ? "" : "; " + guess) + " (one of " +
                easing_list() + ")");
}

// "catmull_rom" or "natural" (or, for spline() and follow(), "linear": straight between the points).
TrackCurve curve_arg(const Bound& b, std::size_t i, bool linear_allowed) {
  const std::string name = b.value(i).as_string();
  if (name == "catmull_rom") return TrackCurve::CatmullRom;
  if (name == "natural") return TrackCurve::Natural;
  if (linear_allowed && name == "linear") return TrackCurve::Eased;
  b.fail(i, "unknown spline \"" + name + "\" (" + (linear_allowed ? "linear, " : "") +
                "catmull_rom or natural)");
}

Value result(const CallArgs& call, Vector3 v, bool number) {
  return number ? finite_number(call, v.x) : finite_vector(call, v);
}

const ParamList kEaseParams = {required("name", kString), required("x", kNumber)};

Value ease_(CallArgs& call) {
  const Bound b = call.bind(kEaseParams);
  return finite_number(call, ease(easing_arg(b, 0), b.number(1)));
}

const ParamList kTrackParams = {required("keys", kinds(ValueKind::List)), optional("time", kNumber),
                                optional("ease", kString, Value::string("linear")),
                                optional("spline", kString)};

Value track_(CallArgs& call) {
  const Bound b = call.bind(kTrackParams);
  const Easing fallback = easing_arg(b, 2);
  std::vector<Keyframe> keys;
  std::optional<bool> numbers;  // every value a number, or every value a vector
  const ParamList key_params = {required("time", kNumber), required("value", kNumberOrVector),
                                optional("ease", kString)};
  for_each_sublist(call, b, 0, "keys", "key", "[time, value] or [time, value, easing]",
                   [&](const Bound& one, std::size_t k) {
                     const std::size_t n = sequence_size(one.value(0));
                     if (n < 2 || n > 3)
                       b.fail(0, "key " + std::to_string(k) + " has " + std::to_string(n) +
                                     " items; a key is [time, value] or [time, value, \"easing\"]");
                     std::vector<Arg> args;
                     for (std::size_t j = 0; j < n; ++j)
                       args.push_back(Arg{"", {}, sequence_item(one.value(0), j), one.span(0)});
                     const CallArgs key(call.site(), std::move(args), call.budget());
                     const Bound kb = key.bind(key_params);
                     const bool is_number = kb.value(1).is(ValueKind::Number);
                     if (numbers && *numbers != is_number)
                       b.fail(0, "key " + std::to_string(k) + "'s value is " +
                                     kind_with_article(kb.value(1).kind()) + "; a track's values are all " +
                                     (*numbers ? "numbers" : "vectors"));
                     numbers = is_number;
                     const Vector3 value = is_number ? Vector3{kb.number(1), 0, 0} : kb.vector(1);
                     keys.push_back({kb.number(0), value, kb.present(2) ? easing_arg(kb, 2) : fallback});
                   });
  try {
    check_keys(keys);
  } catch (const std::invalid_argument& e) {
    b.fail(0, e.what());
  }
  const TrackCurve curve = b.present(3) ? curve_arg(b, 3, false) : TrackCurve::Eased;
  const double at = b.present(1) ? b.number(1) : call.time().frame;
  return result(call, evaluate_track(keys, curve, at), *numbers);
}

const ParamList kSplineParams = {required("points", kinds(ValueKind::List)), required("u", kNumber),
                                 optional("kind", kString, Value::string("catmull_rom"))};

Value spline_(CallArgs& call) {
  const Bound b = call.bind(kSplineParams);
  const std::vector<Vector3> vs = b.vectors(0);
  if (vs.empty()) b.fail(0, "needs at least one point");
  std::vector<Point3> points;
  for (const Vector3& v : vs) points.push_back(to_point(v));
  return finite_vector(call, path_point(points, curve_arg(b, 2, true), b.number(1)));
}

const ParamList kFollowParams = {required("path", kinds(ValueKind::List)),
                                 required("t", kNumber),
                                 optional("up", kVector, Value::vector({0, 0, 1})),
                                 optional("bank", kNumber, Value::number(0)),
                                 optional("fov", kNumber, Value::number(40)),
                                 optional("aspect", kNumber),
                                 optional("kind", kString, Value::string("catmull_rom"))};

Value follow_(CallArgs& call) {
  const Bound b = call.bind(kFollowParams);
  FollowParameters p;
  for (const Vector3& v : b.vectors(0)) p.path.push_back(to_point(v));
  p.t = b.number(1);
  p.up = b.vector(2);
  p.bank_deg = b.number(3);
  p.fov_deg = b.number(4);
  if (b.present(5)) p.aspect = b.positive(5);
  p.curve = curve_arg(b, 6, true);
  return make_camera(b, kFollowParams, [&] { return follow_camera(p); });
}

const BuiltinEntry kAnimationBuiltins[] = {
    {"ease",
     "ease(name, x)  (name: \"linear\", \"in_out_cubic\", ...; x from 0 to 1)",
     ease_,
     "An easing curve at x: 0 at 0, 1 at 1, shaped in between (step, smoothstep, sine, quad, cubic, quart, "
     "expo, back).",
     {&kEaseParams}},
    {"track",
     "track(keys, time: frame, ease: \"linear\", spline: none)  (keys: [[time, value], [time, value, ease], "
     "...])",
     track_,
     "Keyframes: the value at `time` (the frame drawn unless given), eased between keys or on a catmull_rom "
     "or natural "
     "spline through them.",
     {&kTrackParams}},
    {"spline",
     "spline(points, u, kind: \"catmull_rom\")  (u from 0 at the first point to 1 at the last)",
     spline_,
     "A point of the smooth path through the points: catmull_rom, natural or linear.",
     {&kSplineParams}},
    {"follow",
     "follow(path, t, up: (0, 0, 1), bank: 0, fov: 40, aspect:, kind: \"catmull_rom\")",
     follow_,
     "A camera flying along the path through the points, looking along it and banking into turns.",
     {&kFollowParams}},
};

}  // namespace

void register_animation_builtins(BuiltinTable& table) { table.add_all(kAnimationBuiltins); }

}  // namespace hlr::runtime
