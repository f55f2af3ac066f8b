// Option lists of statements — `(margin: 10)`, `(colour: "red")`, a plotter's `{ unit: 0.025 }`, a view's
// `scale: 0.5` — checked in the manner of a solid's options: a missing name, an unknown name, a name given
// twice, a value of the wrong kind or out of range is an error at that option, with the list of options as
// the hint.
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/format_number.hpp"
#include "lang/ast.hpp"
#include "runtime/eval/eval_detail.hpp"
#include "runtime/values/format_value.hpp"
#include "runtime/values/placement.hpp"
#include "runtime/values/value.hpp"

namespace hlr::runtime {

struct OptionSpec {
  std::string_view name;
  ValueKind kind;
  std::string_view alias = {};  // another spelling of the same option ("color")
  bool drawable = false;        // instead of `kind`: a solid, a group or a list of them
};

struct OptionList {
  std::string who;      // "paper 'A4': ", prefixed to every message
  std::string noun;     // "option", or "key" for a plotter's entries
  std::string example;  // "margin: 10", for an option without a name
  std::string hint;     // what the options are
  std::vector<OptionSpec> specs;
};

struct GivenOption {
  Value value;
  lang::SourceSpan span;  // the whole `name: value`
  std::string written;    // the name as written ("color" for colour)
};
using GivenOptions = std::map<std::string, GivenOption, std::less<>>;

inline std::string kind_wanted(ValueKind kind) {
  switch (kind) {
    case ValueKind::Number:
      return "a number";
    case ValueKind::Bool:
      return "true or false";
    case ValueKind::String:
      return "a string";
    default:
      return kind_with_article(kind);
  }
}

// Checks names and kinds, evaluating the values in written order; by canonical name.
template <typename Eval>
GivenOptions check_options(const std::vector<lang::Argument>& args, const OptionList& list, Eval&& eval) {
  GivenOptions given;
  for (const lang::Argument& arg : args) {
    if (!arg.label)
      fail(arg.span, list.who + "each " + list.noun + " needs a name, as in '" + list.example + "'",
           list.hint);
    const std::string& name = arg.label->text;
    const auto spec = std::find_if(list.specs.begin(), list.specs.end(),
                                   [&](const OptionSpec& s) { return s.name == name || s.alias == name; });
    if (spec == list.specs.end()) {
      std::vector<std::string> names;
      for (const OptionSpec& s : list.specs) names.emplace_back(s.name);
      const std::string guess = did_you_mean(name, names);
      fail(arg.span, list.who + "unknown " + list.noun + " '" + name + "'",
           guess.empty() ? list.hint : guess + " " + list.hint);
    }
    const std::string canonical(spec->name);
    if (const auto first = given.find(canonical); first != given.end()) {
      lang::Diagnostic d;
      d.span = arg.span;
      d.message = list.who + list.noun + " '" + name + "' is given twice";
      if (first->second.written != name) d.message += " (as '" + first->second.written + "' before)";
      d.hint = list.hint;
      d.notes.push_back({first->second.span, "first given here"});
      throw EvalError(std::move(d));
    }
    Value value = eval(*arg.value);
    if (spec->drawable ? !is_drawable(value) : !value.is(spec->kind))
      fail(
          arg.span,
          list.who + list.noun + " '" + name + "' must be " +
              (spec->drawable ? std::string("a solid, a group or a list of them") : kind_wanted(spec->kind)) +
              ", got " + kind_with_article(value.kind()),
          list.hint);
    given.emplace(canonical, GivenOption{std::move(value), arg.span, name});
  }
  return given;
}

inline const GivenOption* find(const GivenOptions& given, std::string_view name) {
  const auto it = given.find(name);
  return it == given.end() ? nullptr : &it->second;
}

// A number option within a range: `ok(x)` says whether x is allowed, `range` says what is.
template <typename Ok>
double number_in(const GivenOption& option, const OptionList& list, Ok&& ok, const std::string& range) {
  const double x = option.value.as_number();
  if (!std::isfinite(x) || !ok(x))
    fail(option.span,
         list.who + list.noun + " '" + option.written + "' must be " + range + " (got " +
             format_for_message(x) + ")",
         list.hint);
  return x;
}

inline bool whole(double x) { return std::floor(x) == x; }

}  // namespace hlr::runtime
