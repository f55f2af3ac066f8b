#include "runtime/values/value.hpp"

#include <algorithm>

#include "runtime/values/function.hpp"

namespace hlr::runtime {

const char* kind_name(ValueKind kind) {
  switch (kind) {
    case ValueKind::None:
      return "none";
    case ValueKind::Number:
      return "number";
    case ValueKind::Bool:
      return "bool";
    case ValueKind::String:
      return "string";
    case ValueKind::Vector:
      return "vector";
    case ValueKind::List:
    case ValueKind::Range:  // a range is a list to the user
      return "list";
    case ValueKind::Transform:
      return "transform";
    case ValueKind::Solid:
      return "solid";
    case ValueKind::Group:
      return "group";
    case ValueKind::Camera:
      return "camera";
    case ValueKind::Function:
      return "function";
  }
  return "value";
}

std::string kind_with_article(ValueKind kind) {
  if (kind == ValueKind::None) return "none";
  return std::string("a ") + kind_name(kind);  // no kind name starts with a vowel
}

std::string describe_kinds(KindSet set) {
  std::vector<std::string> names;
  for (unsigned k = 0; k <= static_cast<unsigned>(ValueKind::Function); ++k) {
    const auto kind = static_cast<ValueKind>(k);
    if (kind == ValueKind::Range || !(set & kinds(kind))) continue;
    names.push_back(kind_with_article(kind));
  }
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? " or " : ", ";
    out += names[i];
  }
  return out.empty() ? "nothing" : out;
}

std::size_t sequence_size(const Value& v) {
  return v.is(ValueKind::Range) ? v.as_range().count : v.as_list().size();
}

Value sequence_item(const Value& v, std::size_t i) {
  return v.is(ValueKind::Range) ? Value::number(v.as_range().at(i)) : v.as_list()[i];
}

namespace {

bool same_affine(const Affine3& a, const Affine3& b) { return a.m == b.m && a.t == b.t; }

}  // namespace

bool values_equal(const Value& a, const Value& b) {
  if (a.is_sequence() && b.is_sequence()) {
    const std::size_t n = sequence_size(a);
    if (n != sequence_size(b)) return false;
    for (std::size_t i = 0; i < n; ++i)
      if (!values_equal(sequence_item(a, i), sequence_item(b, i))) return false;
    return true;
  }
  if (a.kind() != b.kind()) return false;
  switch (a.kind()) {
    case ValueKind::None:
      return true;
    case ValueKind::Number:
      return a.as_number() == b.as_number();
    case ValueKind::Bool:
      return a.as_bool() == b.as_bool();
    case ValueKind::String:
      return a.as_string() == b.as_string();
    case ValueKind::Vector:
      return a.as_vector() == b.as_vector();
    case ValueKind::Transform:
      return same_affine(a.as_transform(), b.as_transform());
    case ValueKind::Solid:
      return a.as_solid().solid == b.as_solid().solid && a.as_solid().name == b.as_solid().name;
    case ValueKind::Group:
      return &a.as_group() == &b.as_group();
    case ValueKind::Camera:
      return &a.as_camera() == &b.as_camera();
    case ValueKind::Function:
      return a.as_function() == b.as_function();
    case ValueKind::List:
    case ValueKind::Range:
      break;  // handled above
  }
  return false;
}

}  // namespace hlr::runtime
