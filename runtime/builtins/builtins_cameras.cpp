// Cameras: lookat, ortho, orbit (Albers), desens (Desens' twelve degrees of freedom), built by
// core/camera. A CameraError names the parameter; it is reported at that argument.
#include <stdexcept>

#include "core/camera/camera_adjust.hpp"
#include "core/camera/desens_camera.hpp"
#include "core/camera/lookat_camera.hpp"
#include "core/camera/orbit_camera.hpp"
#include "core/camera/ortho_camera.hpp"
#include "runtime/builtins/builtins.hpp"

namespace hlr::runtime {
namespace {

constexpr KindSet kNumber = kinds(ValueKind::Number);
constexpr KindSet kVector = kinds(ValueKind::Vector);

const ParamList kLookatParams = {required("eye", kVector),
                                 required("target", kVector),
                                 optional("up", kVector, Value::vector({0, 0, 1})),
                                 optional("fov", kNumber, Value::number(40)),
                                 optional("aspect", kNumber),
                                 optional("near", kNumber)};

Value lookat_(CallArgs& call) {
  const Bound b = call.bind(kLookatParams);
  LookatParameters p;
  p.eye = b.point(0);
  p.target = b.point(1);
  p.up = b.vector(2);
  p.fov_deg = b.number(3);
  if (b.present(4)) p.aspect = b.positive(4);
  if (b.present(5)) p.near = b.positive(5);
  return make_camera(b, kLookatParams, [&] { return lookat_camera(p); });
}

const ParamList kOrthoParams = {required("eye", kVector), required("target", kVector),
                                optional("up", kVector, Value::vector({0, 0, 1})),
                                required("height", kNumber), optional("aspect", kNumber)};

Value ortho_(CallArgs& call) {
  const Bound b = call.bind(kOrthoParams);
  OrthoParameters p;
  p.eye = b.point(0);
  p.target = b.point(1);
  p.up = b.vector(2);
  p.height = b.number(3);
  if (b.present(4)) p.aspect = b.positive(4);
  return make_camera(b, kOrthoParams, [&] { return ortho_camera(p); });
}

const ParamList kOrbitParams = {
    optional("theta", kNumber, Value::number(45)), optional("phi", kNumber, Value::number(90)),
    optional("rho", kNumber, Value::number(425)), optional("d", kNumber, Value::number(1549))};

Value orbit_(CallArgs& call) {
  const Bound b = call.bind(kOrbitParams);
  OrbitParameters p;
  p.theta_deg = b.number(0);
  p.phi_deg = b.number(1);
  p.rho = b.number(2);
  p.d = b.number(3);
  return make_camera(b, kOrbitParams, [&] { return orbit_camera(p); });
}

const ParamList kDesensParams = {
    required("object", kVector),
    optional("attitude", kVector, Value::vector({})),
    required("observer", kVector),
    optional("heading", kVector, Value::vector({})),
    optional("focal", kNumber, Value::number(1.5)),
    optional("scale", kNumber, Value::number(0.5)),
    optional("offset", kinds(ValueKind::Vector, ValueKind::List), Value::vector({0, 0, 0})),
    optional("thesis_pi", kinds(ValueKind::Bool), Value::boolean(false))};

Value desens_(CallArgs& call) {
  const Bound b = call.bind(kDesensParams);
  DesensParameters p;
  p.object_position = b.point(0);
  p.attitude = b.vector(1);
  p.observer_position = b.point(2);
  p.heading = b.vector(3);
  p.focal = b.number(4);
  p.scale = b.number(5);
  // A 2-D value: (yoff, zoff), the point (yoff, zoff, 0), or the list [yoff, zoff] older scripts wrote.
  if (b.value(6).is(ValueKind::Vector)) {
    const Vector3 v = b.vector(6);
    if (v.z != 0) b.fail(6, "must be two numbers (yoff, zoff), got a third one");
    p.offset = {v.x, v.y};
  } else {
    const std::vector<double> offset = b.numbers(6);
    if (offset.size() != 2) b.fail(6, "must be two numbers (yoff, zoff)");
    p.offset = {offset[0], offset[1]};
  }
  p.thesis_pi = b.boolean(7);
  return make_camera(b, kDesensParams, [&] { return desens_camera(p); });
}

const ParamList kAdjustParams = {
    required("camera", kinds(ValueKind::Camera)), optional("theta", kNumber, Value::number(0)),
    optional("phi", kNumber, Value::number(0)),   optional("zoom", kNumber, Value::number(1)),
    optional("dolly", kNumber, Value::number(0)), optional("pivot", kVector, Value::vector({0, 0, 0}))};

// adjust(camera, theta:, phi:, zoom:, dolly:, pivot:): Albers' keys for any camera (the REPL's :orbit,
// :zoom and :dolly save as this).
Value adjust_(CallArgs& call) {
  const Bound b = call.bind(kAdjustParams);
  CameraAdjustment a;
  a.theta_deg = b.number(1);
  a.phi_deg = b.number(2);
  a.zoom = b.number(3);
  a.dolly = b.number(4);
  a.pivot = b.point(5);
  return make_camera(b, kAdjustParams, [&] { return adjusted_camera(b.value(0).as_camera(), a); });
}

const BuiltinEntry kCameraBuiltins[] = {
    {"lookat",
     "lookat(eye:, target:, up: (0, 0, 1), fov: 40, aspect:, near:)",
     lookat_,
     "A perspective camera at eye looking at target, fov degrees wide.",
     {&kLookatParams}},
    {"ortho",
     "ortho(eye:, target:, up: (0, 0, 1), height:, aspect:)",
     ortho_,
     "A parallel-projection camera from eye towards target showing height units vertically.",
     {&kOrthoParams}},
    {"orbit",
     "orbit(theta: 45, phi: 90, rho: 425, d: 1549)",
     orbit_,
     "Albers' camera at distance rho from the origin, azimuth theta and polar angle phi, looking at the "
     "origin.",
     {&kOrbitParams}},
    {"desens",
     "desens(object:, attitude: (0, 0, 0), observer:, heading: (0, 0, 0), focal: 1.5, scale: 0.5, "
     "offset: (0, 0), thesis_pi: false)",
     desens_,
     "Desens' 1969 camera of twelve degrees of freedom: the object's and observer's positions and angles.",
     {&kDesensParams}},
    {"adjust",
     "adjust(camera, theta: 0, phi: 0, zoom: 1, dolly: 0, pivot: (0, 0, 0))",
     adjust_,
     "A camera stepped as Albers' keys do: turned theta and phi degrees about the pivot, zoomed and dollied.",
     {&kAdjustParams}},
};

}  // namespace

void register_camera_builtins(BuiltinTable& table) { table.add_all(kCameraBuiltins); }

}  // namespace hlr::runtime
