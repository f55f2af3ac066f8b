#include "runtime/builtins/builtins.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "core/format_number.hpp"
#include "runtime/base/eval_error.hpp"
#include "runtime/builtins/solid_cache.hpp"
#include "runtime/values/format_value.hpp"
#include "runtime/values/placement.hpp"

namespace hlr::runtime {

void BuiltinTable::add(const BuiltinEntry& entry) {
  auto f = std::make_shared<Function>();
  f->name = entry.name;
  f->body = BuiltinFunction{entry.impl, entry.signature, entry.summary, entry.forms};
  entries_.insert_or_assign(entry.name, Value::function(std::move(f)));
}

void BuiltinTable::add_constant(const std::string& name, Value value) {
  entries_.insert_or_assign(name, std::move(value));
}

const Value* BuiltinTable::find(const std::string& name) const {
  const auto it = entries_.find(name);
  return it == entries_.end() ? nullptr : &it->second;
}

std::vector<std::string> BuiltinTable::names() const {
  std::vector<std::string> out;
  for (const auto& e : entries_) out.push_back(e.first);
  std::sort(out.begin(), out.end());
  return out;
}

const BuiltinTable& builtins() {
  static const BuiltinTable table = [] {
    BuiltinTable t;
    register_math_builtins(t);
    register_core_builtins(t);
    register_vector_builtins(t);
    register_transform_builtins(t);
    register_solid_builtins(t);
    register_shape_builtins(t);

    register_camera_builtins(t);
    register_animation_builtins(t);
    register_import_builtins(t);
    register_hatch_builtins(t);
    register_boolean_builtins(t);
    return t;
  }();
  return table;
}

namespace {

// "sqrt(-1)": the call as the user would write it, from the argument values.
std::string call_text(const CallArgs& call) {
  std::string text = call.site().function + "(";
  for (std::size_t i = 0; i < call.args().size(); ++i) {
    const Arg& a = call.args()[i];
    if (i) text += ", ";
    if (!a.label.empty()) text += a.label + ": ";
    try {
      text += display(a.value, 80);
    } catch (const FormatError&) {
      text += "...";
    }
  }
  return text + ")";
}

[[noreturn]] void not_finite(const CallArgs& call, bool nan) {
  fail(call.site().span, call_text(call) + (nan ? " is not a real number" : " overflows"),
       nan ? "check the arguments' domain" : "the result is beyond the largest number (about 1.8e308)");
}

}  // namespace

Value finite_number(const CallArgs& call, double x) {
  if (!std::isfinite(x)) not_finite(call, std::isnan(x));
  return Value::number(x);
}

Value finite_vector(const CallArgs& call, Vector3 v) {
  if (!is_finite(to_point(v))) not_finite(call, std::isnan(v.x) || std::isnan(v.y) || std::isnan(v.z));
  return Value::vector(v);
}

std::vector<PlacedSolid> solids_where_placed(const CallArgs& call, const Value& value,
                                             const lang::SourceSpan& span) {
  std::vector<PlacedSolid> members =
      value.is(ValueKind::Solid)
          ? std::vector<PlacedSolid>{{value.as_solid().solid, value.as_solid().name, Affine3::identity()}}
          : flatten_placed(value, Affine3::identity(), span, call.site().function + "()", call.budget());
  const Affine3 identity = Affine3::identity();
  for (PlacedSolid& m : members) {
    const Affine3 t = m.worldFromObject;
    if (t.m == identity.m && t.t == identity.t) continue;
    const std::shared_ptr<const Solid> source = m.solid;
    m.solid = SolidCache::shared().placed(
        source, t, [&] { return std::make_shared<const Solid>(source->transformed(t)); });
    m.worldFromObject = identity;
  }
  return members;
}

Value generated_solid(const CallArgs& call, std::size_t faces, const std::function<Solid()>& make) {
  call.budget().charge_faces_built(call.site().span, faces);
  try {
    // Keyed by the built-in's signature, not the name it was called by (a script may rename built-ins).
    return Value::solid(SolidCache::shared().generated(std::string(call.site().signature), call.args(),
                                                       [&] { return std::make_shared<const Solid>(make()); }),
                        call.site().function);
  } catch (const EvalError&) {
    throw;
  } catch (const std::invalid_argument& e) {
    call.fail_call(e.what());
  } catch (const std::runtime_error& e) {
    // The generator's builder rejected the shape these arguments describe (a self-crossing outline, ...).
    std::string detail = e.what();
    const auto newline = detail.find('\n');
    detail = newline == std::string::npos ? std::string() : detail.substr(newline + 1);
    call.fail_call(call.site().function + "() cannot build a valid solid from these arguments" +
                   (detail.empty() ? std::string() : ":" + detail));
  }
}

Param crease_param(double fallback) {
  return optional("crease", kinds(ValueKind::Number), Value::number(fallback));
}

void for_each_sublist(const CallArgs& call, const Bound& b, std::size_t i, std::string_view param,
                      const std::string& item, const std::string& expected,
                      const std::function<void(const Bound& one, std::size_t k)>& visit) {
  const std::vector<Param> one_param = {required(param, kinds(ValueKind::List))};
  const Value& list = b.value(i);
  for (std::size_t k = 0; k < sequence_size(list); ++k) {
    const Value sub = sequence_item(list, k);
    if (!sub.is_sequence())
      b.fail(i, item + " " + std::to_string(k) + " is " + kind_with_article(sub.kind()) + ", expected " +
                    expected);
    const CallArgs one(call.site(), {Arg{"", {}, sub, b.span(i)}}, call.budget());
    visit(one.bind(one_param), k);
  }
}

Param contours_param() { return optional("contours", kinds(ValueKind::String), Value::string("edges")); }

bool smooth_contours(const Bound& b, std::size_t i) {
  const std::string& v = b.value(i).as_string();
  if (v != "smooth" && v != "edges") b.fail(i, "must be \"smooth\" or \"edges\" (got \"" + v + "\")");
  return v == "smooth";
}

Solid with_contours(Solid solid, bool smooth) {
  solid.smooth_contours = smooth;
  return solid;
}

double crease_angle(const Bound& b, std::size_t i) {
  const double deg = b.number(i);
  if (!(deg >= 0 && deg <= 180))
    b.fail(i, "must be between 0 and 180 degrees (got " + format_for_message(deg) + ")");
  return deg;
}

}  // namespace hlr::runtime
