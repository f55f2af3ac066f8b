// union(), difference(), intersection(): booleans of solids (stdlib/booleans.hpp). Each argument is a solid,
// a group or a list of them (placed solids are taken where they are placed) and stands for the union of
// what it holds; the result is a solid in those coordinates, cached across frames like a generator's.
#include <string>

#include "runtime/builtins/builtins.hpp"
#include "runtime/builtins/solid_cache.hpp"
#include "runtime/values/placement.hpp"
#include "stdlib/booleans.hpp"

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
};

}  // namespace

void register_boolean_builtins(BuiltinTable& table) { table.add_all(kBooleanBuiltins); }

}  // namespace hlr::runtime
