#include "runtime/values/placement.hpp"

#include "runtime/base/eval_error.hpp"

namespace hlr::runtime {

bool is_drawable(const Value& value) {
  return value.is(ValueKind::Solid) || value.is(ValueKind::Group) || value.is(ValueKind::List);
}

namespace {

void collect(const Value& value, const Affine3& then, const lang::SourceSpan& span, const std::string& what,
             Budget& budget, const std::string& path, int depth, std::vector<PlacedSolid>& out) {
  budget.step(span);
  if (value.is(ValueKind::Solid)) {
    out.push_back({value.as_solid().solid, value.as_solid().name, then});
    return;
  }
  if (value.is(ValueKind::Group)) {
    for (const PlacedSolid& m : value.as_group())
      out.push_back({m.solid, m.name, m.worldFromObject.then(then)});
    return;
  }
  if (value.is(ValueKind::List) && depth < 64) {
    const List& items = value.as_list();
    for (std::size_t i = 0; i < items.size(); ++i)
      collect(items[i], then, span, what, budget, path + "[" + std::to_string(i) + "]", depth + 1, out);
    return;
  }
  const std::string where = path.empty() ? std::string() : " (item " + path + ")";
  fail(span,
       what + " needs a solid, a group or a list of them, got " + kind_with_article(value.kind()) + where,
       "solids come from 'solid NAME { ... }' or generators such as box(1, 2, 3)");
}

}  // namespace

std::vector<PlacedSolid> flatten_placed(const Value& value, const Affine3& then, const lang::SourceSpan& span,
                                        const std::string& what, Budget& budget) {
  std::vector<PlacedSolid> out;
  collect(value, then, span, what, budget, "", 0, out);
  return out;
}

}  // namespace hlr::runtime
