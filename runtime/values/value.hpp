// The values of hlrscript (runtime/LANGUAGE_SPEC.md, "Values"). A Value is small and cheap to copy:
// lists, transforms, solids, groups, cameras and functions are shared immutable objects, so passing
// them around never copies geometry. Values are immutable; `+` on lists builds a new list.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/geometry/affine3.hpp"
#include "core/geometry/vector.hpp"
#include "core/solid/solid.hpp"

namespace hlr::runtime {

struct Function;  // function.hpp
class Value;
using List = std::vector<Value>;

// In the order of ValueData's alternatives: kind() is the variant index.
enum class ValueKind : std::uint8_t {
  None,
  Number,
  Bool,
  String,
  Vector,
  List,
  Range,
  Transform,
  Solid,
  Group,
  Camera,
  Function
};

// a..b and range(a, b, step): a list whose items are computed, so `for i in 0..1000000` allocates nothing.
struct RangeValue {
  double start = 0;
  double step = 1;
  std::size_t count = 0;
  double at(std::size_t i) const { return start + step * static_cast<double>(i); }
};

// A validated solid and the name it is drawn under: the `solid` statement's name, or the generator's
// ("box") for an anonymous result.
struct SolidValue {
  std::shared_ptr<const Solid> solid;
  std::string name;
};

struct PlacedSolid {
  std::shared_ptr<const Solid> solid;
  std::string name;
  Affine3 worldFromObject;
};

struct GroupValue {
  std::shared_ptr<const std::vector<PlacedSolid>> members;
};

using ValueData =
    std::variant<std::monostate, double, bool, std::string, Vector3, std::shared_ptr<const List>, RangeValue,
                 std::shared_ptr<const Affine3>, SolidValue, GroupValue, std::shared_ptr<const Camera>,
                 std::shared_ptr<const Function>>;

class Value {
 public:
  Value() = default;  // none
  explicit Value(ValueData data) : data_(std::move(data)) {}

  static Value number(double x) { return Value(ValueData(std::in_place_type<double>, x)); }
  static Value boolean(bool b) { return Value(ValueData(std::in_place_type<bool>, b)); }
  static Value string(std::string s) {
    return Value(ValueData(std::in_place_type<std::string>, std::move(s)));
  }
  static Value vector(Vector3 v) { return Value(ValueData(v)); }
  static Value list(List items) { return Value(ValueData(std::make_shared<const List>(std::move(items)))); }
  static Value range(RangeValue r) { return Value(ValueData(r)); }
  static Value transform(const Affine3& a) { return Value(ValueData(std::make_shared<const Affine3>(a))); }
  static Value solid(std::shared_ptr<const Solid> s, std::string name) {
    return Value(ValueData(SolidValue{std::move(s), std::move(name)}));
  }
  static Value group(std::vector<PlacedSolid> members) {
    return Value(ValueData(GroupValue{std::make_shared<const std::vector<PlacedSolid>>(std::move(members))}));
  }
  static Value camera(const Camera& c) { return Value(ValueData(std::make_shared<const Camera>(c))); }
  static Value function(std::shared_ptr<const Function> f) { return Value(ValueData(std::move(f))); }

  ValueKind kind() const { return static_cast<ValueKind>(data_.index()); }
  bool is(ValueKind k) const { return kind() == k; }
  bool is_none() const { return kind() == ValueKind::None; }
  // A list or a range: anything `for` can walk and `[i]` can index.
  bool is_sequence() const { return kind() == ValueKind::List || kind() == ValueKind::Range; }

  double as_number() const { return std::get<double>(data_); }
  bool as_bool() const { return std::get<bool>(data_); }
  const std::string& as_string() const { return std::get<std::string>(data_); }
  Vector3 as_vector() const { return std::get<Vector3>(data_); }
  const List& as_list() const { return *std::get<std::shared_ptr<const List>>(data_); }
  const RangeValue& as_range() const { return std::get<RangeValue>(data_); }
  const Affine3& as_transform() const { return *std::get<std::shared_ptr<const Affine3>>(data_); }
  const SolidValue& as_solid() const { return std::get<SolidValue>(data_); }
  const std::vector<PlacedSolid>& as_group() const { return *std::get<GroupValue>(data_).members; }
  const Camera& as_camera() const { return *std::get<std::shared_ptr<const Camera>>(data_); }
  const std::shared_ptr<const Function>& as_function() const {
    return std::get<std::shared_ptr<const Function>>(data_);
  }

  const ValueData& data() const { return data_; }

 private:
  ValueData data_;
};

// Bit sets of kinds, for argument checking.
using KindSet = std::uint32_t;
constexpr KindSet kinds(ValueKind k) { return KindSet{1} << static_cast<unsigned>(k); }
template <typename... K>
constexpr KindSet kinds(ValueKind k, K... more) {
  return kinds(k) | kinds(more...);
}
inline constexpr KindSet kAnyKind = ~KindSet{0};

const char* kind_name(ValueKind kind);          // "number", "list" (a range is a "list" to the user)
std::string kind_with_article(ValueKind kind);  // "a number", "an integer"...
std::string describe_kinds(KindSet set);        // "a number or a vector"

// Length and items of a list or a range.
std::size_t sequence_size(const Value& v);
Value sequence_item(const Value& v, std::size_t i);

// Structural equality of two values of the same kind (solids, cameras, functions: the same object).
bool values_equal(const Value& a, const Value& b);

}  // namespace hlr::runtime
