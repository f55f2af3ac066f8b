#include "runtime/values/arguments.hpp"

#include <cmath>

#include "core/format_number.hpp"
#include "runtime/base/did_you_mean.hpp"
#include "runtime/base/eval_error.hpp"
#include "runtime/base/source_table.hpp"
#include "runtime/values/format_value.hpp"

namespace hlr::runtime {

std::vector<int> match_arguments(const CallSite& site, const std::vector<Arg>& args,
                                 const std::vector<std::string_view>& names,
                                 const std::vector<bool>& required) {
  const auto who = [&] { return site.function + "()"; };  // built only for a message
  std::vector<int> slots(names.size(), -1);
  std::size_t next = 0;  // next positional parameter
  for (std::size_t a = 0; a < args.size(); ++a) {
    const Arg& arg = args[a];
    if (arg.label.empty()) {
      if (next >= names.size()) {
        const std::string takes = names.empty() ? "no arguments" : "at most " + std::to_string(names.size());
        fail(
            arg.span,
            "too many arguments to " + who() + ": it takes " + takes + ", got " + std::to_string(args.size()),
            std::string(site.signature));
      }
      slots[next++] = static_cast<int>(a);
      continue;
    }
    std::size_t p = 0;
    while (p < names.size() && names[p] != arg.label) ++p;
    if (p == names.size()) {
      const std::string guess = did_you_mean(arg.label, std::vector<std::string>(names.begin(), names.end()));
      fail(arg.label_span, "unknown argument '" + arg.label + "' to " + who(),
           (guess.empty() ? "" : guess + " ") + std::string(site.signature));
    }
    if (slots[p] >= 0)
      fail(arg.label_span, "argument '" + arg.label + "' to " + who() + " is given twice",
           std::string(site.signature));
    slots[p] = static_cast<int>(a);
  }
  for (std::size_t p = 0; p < names.size(); ++p)
    if (required[p] && slots[p] < 0)
      fail(site.span, "missing argument '" + std::string(names[p]) + "' to " + who(),
           std::string(site.signature));
  return slots;
}

std::size_t CallArgs::positional_count() const {
  std::size_t n = 0;
  for (const Arg& a : args_) n += a.label.empty() ? 1 : 0;
  return n;
}

std::filesystem::path CallArgs::script_directory() const {
  const SourceEntry* entry = sources_ ? sources_->entry(site_.span.file) : nullptr;
  return entry ? entry->path.parent_path() : std::filesystem::current_path();
}

const FileAccess* CallArgs::file_access() const { return sources_ ? &sources_->access() : nullptr; }

void CallArgs::note_input(const std::filesystem::path& path) const {
  if (sources_) sources_->add_input(path);
}

bool CallArgs::has_label(std::string_view label) const {
  for (const Arg& a : args_)
    if (a.label == label) return true;
  return false;
}

void CallArgs::fail(const lang::SourceSpan& span, const std::string& message) const {
  runtime::fail(span, message, std::string(site_.signature));
}

Bound CallArgs::bind(const std::vector<Param>& params) const {
  std::vector<std::string_view> names;
  std::vector<bool> needed;
  for (const Param& p : params) {
    names.push_back(p.name);
    needed.push_back(p.required);
  }
  std::vector<int> slots = match_arguments(site_, args_, names, needed);
  for (std::size_t p = 0; p < params.size(); ++p) {
    if (slots[p] < 0) continue;
    const Arg& arg = args_[static_cast<std::size_t>(slots[p])];
    ValueKind kind = arg.value.kind();
    if (kind == ValueKind::Range) kind = ValueKind::List;
    if (!(params[p].kinds & kinds(kind)))
      fail(arg.span, "bad argument '" + std::string(params[p].name) + "' to " + site_.function +
                         "(): expected " + describe_kinds(params[p].kinds) + ", got " +
                         kind_with_article(kind));
  }
  return Bound(*this, params, std::move(slots));
}

const Value& Bound::value(std::size_t i) const {
  return slots_[i] >= 0 ? call_.args()[static_cast<std::size_t>(slots_[i])].value : params_[i].fallback;
}

const lang::SourceSpan& Bound::span(std::size_t i) const {
  return slots_[i] >= 0 ? call_.args()[static_cast<std::size_t>(slots_[i])].span : call_.site().span;
}

void Bound::fail(std::size_t i, const std::string& reason) const {
  call_.fail(span(i), "bad argument '" + std::string(params_[i].name) + "' to " + call_.site().function +
                          "(): " + reason);
}

double Bound::positive(std::size_t i) const {
  const double x = number(i);
  if (!(x > 0)) fail(i, "must be positive (got " + format_for_message(x) + ")");
  return x;
}

double Bound::non_negative(std::size_t i) const {
  const double x = number(i);
  if (!(x >= 0)) fail(i, "must not be negative (got " + format_for_message(x) + ")");
  return x;
}

int Bound::whole(std::size_t i, int lo, int hi) const {
  const double x = number(i);
  if (!(x >= lo && x <= hi) || std::floor(x) != x)
    fail(i, "must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + " (got " +
                format_for_message(x) + ")");
  return static_cast<int>(x);
}

std::vector<double> Bound::numbers(std::size_t i) const {
  const Value& v = value(i);
  const std::size_t n = sequence_size(v);
  call_.budget().step(span(i), n);
  std::vector<double> out;
  out.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Value item = sequence_item(v, k);
    if (!item.is(ValueKind::Number))
      fail(i, "item " + std::to_string(k) + " is " + kind_with_article(item.kind()) + ", expected a number");
    out.push_back(item.as_number());
  }
  return out;
}

std::vector<Vector3> Bound::vectors(std::size_t i) const {
  const Value& v = value(i);
  const std::size_t n = sequence_size(v);
  call_.budget().step(span(i), n);
  std::vector<Vector3> out;
  out.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Value item = sequence_item(v, k);
    if (!item.is(ValueKind::Vector))
      fail(i, "item " + std::to_string(k) + " is " + kind_with_article(item.kind()) + ", expected a vector");
    out.push_back(item.as_vector());
  }
  return out;
}

}  // namespace hlr::runtime
