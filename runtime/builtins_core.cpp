// Lists, strings and groups: len, range, str, group, place.
#include <cmath>

#include "core/format_number.hpp"
#include "lang/source.hpp"
#include "runtime/builtins.hpp"
#include "runtime/format_value.hpp"
#include "runtime/placement.hpp"

namespace hlr::runtime {
namespace {

constexpr KindSet kNumber = kinds(ValueKind::Number);

Value len_(CallArgs& call) {
  static const std::vector<Param> params = {required("x", kinds(ValueKind::List, ValueKind::String))};
  const Bound b = call.bind(params);
  if (b.value(0).is(ValueKind::String))
    return Value::number(static_cast<double>(lang::count_code_points(b.value(0).as_string())));
  return Value::number(static_cast<double>(sequence_size(b.value(0))));
}

Value range_(CallArgs& call) {
  static const std::vector<Param> params = {required("a", kNumber), required("b", kNumber),
                                            optional("step", kNumber, Value::number(1))};
  const Bound b = call.bind(params);
  const double start = b.number(0), stop = b.number(1), step = b.number(2);
  if (step == 0) b.fail(2, "must not be 0");
  const double count = std::ceil((stop - start) / step);
  if (!(count <= static_cast<double>(kMaxListItems)))
    call.fail_call(limit_message("items in a list", kMaxListItems) + ": " + call.site().function +
                   "() would make " + format_for_message(count));
  return Value::range({start, step, count > 0 ? static_cast<std::size_t>(count) : 0});
}

Value str_(CallArgs& call) {
  static const std::vector<Param> params = {required("x", kAnyKind)};
  const Bound b = call.bind(params);
  try {
    std::string text = display(b.value(0), kMaxStringLength);
    call.budget().step(call.site().span, text.size() / 16);
    return Value::string(std::move(text));
  } catch (const FormatError& e) {
    call.fail_call(e.what());
  }
}

Value group_(CallArgs& call) {
  static const std::vector<Param> params = {required("list", kinds(ValueKind::List, ValueKind::Group))};
  const Bound b = call.bind(params);
  return Value::group(flatten_placed(b.value(0), Affine3::identity(), b.span(0), "group()", call.budget()));
}

// place(object, T): the object moved by T, as a group (so groups can hold placed parts).
Value place_(CallArgs& call) {
  static const std::vector<Param> params = {
      required("object", kinds(ValueKind::Solid, ValueKind::Group, ValueKind::List)),
      required("transform", kinds(ValueKind::Transform))};
  const Bound b = call.bind(params);
  const Affine3& t = b.value(1).as_transform();
  const double det = t.determinant();
  if (det == 0 || !std::isfinite(det)) b.fail(1, "is singular: it would flatten the solid");
  return Value::group(flatten_placed(b.value(0), t, b.span(0), "place()", call.budget()));
}

const BuiltinEntry kCoreBuiltins[] = {
    {"len", "len(list) | len(string)", len_},
    {"range", "range(a, b, step: 1)", range_},
    {"str", "str(x)", str_},
    {"group", "group(list)", group_},
    {"place", "place(object, transform)", place_},
};

}  // namespace

void register_core_builtins(BuiltinTable& table) { table.add_all(kCoreBuiltins); }

}  // namespace hlr::runtime
