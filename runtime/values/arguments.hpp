// Arguments of a call and their binding to parameters, shared by built-ins and user functions.
// Positional arguments fill parameters in order, named ones (`fov: 40`) by name. Every mistake is an
// error at the argument's span (or the call's, for a missing one) with the function's signature as the
// hint, worded as CameraError does: "bad argument 'fov' to lookat(): ...".
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/geometry/vector.hpp"
#include "lang/source.hpp"
#include "runtime/values/budget.hpp"
#include "runtime/values/frame_time.hpp"
#include "runtime/values/value.hpp"

namespace hlr::runtime {

class SourceTable;
class FileAccess;

struct Arg {
  std::string label;  // empty for a positional argument
  lang::SourceSpan label_span;
  Value value;
  lang::SourceSpan span;  // the value's expression
};

struct CallSite {
  std::string function;        // as the script calls it: "box"
  std::string_view signature;  // "box(sx, sy, sz) | box(min: p, max: q)"; lives as long as the function
  lang::SourceSpan span;       // the whole call
};

struct Param {
  std::string_view name;
  KindSet kinds = kAnyKind;
  bool required = true;
  Value fallback;  // an optional parameter's default; none means "absent"
};
using ParamList = std::vector<Param>;

inline Param required(std::string_view name, KindSet accepted) { return {name, accepted, true, Value()}; }
inline Param optional(std::string_view name, KindSet accepted, Value fallback = Value()) {
  return {name, accepted, false, std::move(fallback)};
}

// Which argument fills each parameter (-1: none). Errors: too many positional arguments, an unknown name,
// a parameter given twice, a required one missing. `required[i]` says whether parameter i must be given.
std::vector<int> match_arguments(const CallSite& site, const std::vector<Arg>& args,
                                 const std::vector<std::string_view>& names,
                                 const std::vector<bool>& required);

class Bound;

// A built-in's view of its call.
class CallArgs {
 public:
  CallArgs(CallSite site, std::vector<Arg> args, Budget& budget, const SourceTable* sources = nullptr,
           const FrameTime* time = nullptr)
      : site_(std::move(site)), args_(std::move(args)), budget_(budget), sources_(sources), time_(time) {}

  const CallSite& site() const { return site_; }
  const std::vector<Arg>& args() const { return args_; }
  std::size_t positional_count() const;
  bool has_label(std::string_view label) const;
  Budget& budget() const { return budget_; }
  // Where in the sequence the frame being evaluated is (frame 0 of 1 when not known).
  FrameTime time() const { return time_ ? *time_ : FrameTime{}; }
  // The directory of the file the call is written in: built-ins that read files (import) resolve
  // relative paths against it. The working directory when unknown.
  std::filesystem::path script_directory() const;
  // What the run's scripts may read (file_access.hpp); nullptr when the call has no program (C++ tests).
  const FileAccess* file_access() const;
  // Records a file a built-in reads as an input of the run (see SourceTable::add_input).
  void note_input(const std::filesystem::path& path) const;

  // Checks names, count and kinds against `params`.
  Bound bind(const std::vector<Param>& params) const;

  // An error at `span` with the signature as the hint.
  [[noreturn]] void fail(const lang::SourceSpan& span, const std::string& message) const;
  [[noreturn]] void fail_call(const std::string& message) const { fail(site_.span, message); }

 private:
  CallSite site_;
  std::vector<Arg> args_;
  Budget& budget_;
  const SourceTable* sources_;
  const FrameTime* time_;
};

// Arguments matched to parameters, with typed accessors that check values ("must be positive").
class Bound {
 public:
  Bound(const CallArgs& call, const std::vector<Param>& params, std::vector<int> slots)
      : call_(call), params_(params), slots_(std::move(slots)) {}

  const Value& value(std::size_t i) const;
  bool given(std::size_t i) const { return slots_[i] >= 0; }
  bool present(std::size_t i) const { return !value(i).is_none(); }  // given, or a default that is not none
  const lang::SourceSpan& span(std::size_t i) const;

  double number(std::size_t i) const { return value(i).as_number(); }
  double positive(std::size_t i) const;      // > 0
  double non_negative(std::size_t i) const;  // >= 0
  // A whole number in [lo, hi].
  int whole(std::size_t i, int lo, int hi) const;
  bool boolean(std::size_t i) const { return value(i).as_bool(); }
  Vector3 vector(std::size_t i) const { return value(i).as_vector(); }
  Point3 point(std::size_t i) const { return to_point(value(i).as_vector()); }
  // A list argument's items, each of the given kind (a range counts as a list of numbers).
  std::vector<double> numbers(std::size_t i) const;
  std::vector<Vector3> vectors(std::size_t i) const;

  // "bad argument 'name' to f(): reason" at the argument.
  [[noreturn]] void fail(std::size_t i, const std::string& reason) const;
  const CallArgs& call() const { return call_; }

 private:
  const CallArgs& call_;
  const std::vector<Param>& params_;
  std::vector<int> slots_;
};

}  // namespace hlr::runtime
