// Lists, strings and groups: len, range, str, group, place.
#include <cmath>

#include "core/format_number.hpp"
#include "lang/source.hpp"
#include "runtime/builtins/builtins.hpp"
#include "runtime/values/format_value.hpp"
#include "runtime/values/placement.hpp"

namespace hlr::runtime {
namespace {

constexpr KindSet kNumber = kinds(ValueKind::Number);

const ParamList kLenParams = {required("x", kinds(ValueKind::List, ValueKind::String))};

Value len_(CallArgs& call) {
  const Bound b = call.bind(kLenParams);
  if (b.value(0).is(ValueKind::String))
    return Value::number(static_cast<double>(lang::count_code_points(b.value(0).as_string())));
  return Value::number(static_cast<double>(sequence_size(b.value(0))));
}

const ParamList kRangeParams = {required("a", kNumber), required("b", kNumber),
                                optional("step", kNumber, Value::number(1))};

Value range_(CallArgs& call) {
  const Bound b = call.bind(kRangeParams);
  const double start = b.number(0), stop = b.number(1), step = b.number(2);
  if (step == 0) b.fail(2, "must not be 0");
  const double count = std::ceil((stop - start) / step);
  const std::size_t limit = call.budget().limits().list;
  if (!(count <= static_cast<double>(limit)))
    call.fail_call(limit_message("items in a list", limit, "list") + ": " + call.site().function +
                   "() would make " + format_for_message(count));
  return Value::range({start, step, count > 0 ? static_cast<std::size_t>(count) : 0});
}

const ParamList kStrParams = {required("x", kAnyKind)};

Value str_(CallArgs& call) {
  const Bound b = call.bind(kStrParams);
  try {
    std::string text = display(b.value(0), call.budget().limits().string);
    call.budget().step(call.site().span, text.size() / 16);
    return Value::string(std::move(text));
  } catch (const FormatError& e) {
    call.fail_call(e.what());
  }
}

const ParamList kGroupParams = {required("list", kinds(ValueKind::List, ValueKind::Group))};

Value group_(CallArgs& call) {
  const Bound b = call.bind(kGroupParams);
  return Value::group(flatten_placed(b.value(0), Affine3::identity(), b.span(0), "group()", call.budget()));
}

const ParamList kPlaceParams = {
    required("object", kinds(ValueKind::Solid, ValueKind::Group, ValueKind::List)),
    required("transform", kinds(ValueKind::Transform))};

// place(object, T): the object moved by T, as a group (so groups can hold placed parts).
Value place_(CallArgs& call) {
  const Bound b = call.bind(kPlaceParams);
  const Affine3& t = b.value(1).as_transform();
  const double det = t.determinant();
  if (det == 0 || !std::isfinite(det)) b.fail(1, "is singular: it would flatten the solid");
  return Value::group(flatten_placed(b.value(0), t, b.span(0), "place()", call.budget()));
}

const BuiltinEntry kCoreBuiltins[] = {
    {"len",
     "len(x)  (x a list or a string)",
     len_,
     "The number of items in a list, or of characters (code points) in a string.",
     {&kLenParams}},
    {"range",
     "range(a, b, step: 1)",
     range_,
     "The numbers from a towards b, b excluded, step apart, as a range.",
     {&kRangeParams}},
    {"str", "str(x)", str_, "Any value as text, as string interpolation shows it.", {&kStrParams}},
    {"group",
     "group(list)",
     group_,
     "The solids of a list or group, nested lists flattened, as one group.",
     {&kGroupParams}},
    {"place",
     "place(object, transform)",
     place_,
     "A solid, group or list of them moved by a transform, as a group.",
     {&kPlaceParams}},
};

}  // namespace

void register_core_builtins(BuiltinTable& table) { table.add_all(kCoreBuiltins); }

}  // namespace hlr::runtime
