// Calls: built-ins through their registration tables, user functions as closures with named and
// default parameters. The call depth is limited (Limits::calls); an error inside a function carries
// notes pointing at the calls that led there.
#include "runtime/eval/eval_detail.hpp"
#include "runtime/eval/evaluator.hpp"

namespace hlr::runtime {

namespace {

// Restores the call depth on every exit path.
class CallDepth {
 public:
  explicit CallDepth(std::size_t& depth) : depth_(depth) { ++depth_; }
  ~CallDepth() { --depth_; }
  CallDepth(const CallDepth&) = delete;
  CallDepth& operator=(const CallDepth&) = delete;

 private:
  std::size_t& depth_;
};

}  // namespace

Value Evaluator::eval_call(const lang::CallExpr& call, const lang::Expr& expr, const ScopePtr& scope) {
  const Value callee = eval(*call.callee, scope);
  if (!callee.is(ValueKind::Function)) {
    const auto* ref = std::get_if<lang::NameRef>(&call.callee->node);
    fail(call.callee->span, (ref ? "'" + ref->name + "' is " : std::string("this is ")) +
                                kind_with_article(callee.kind()) + ", not a function");
  }
  std::vector<Arg> args;
  args.reserve(call.args.size());
  for (const lang::Argument& a : call.args) {
    Arg arg;
    if (a.label) {
      arg.label = a.label->text;
      arg.label_span = a.label->span;
    }
    arg.value = eval(*a.value, scope);
    arg.span = a.value->span;
    args.push_back(std::move(arg));
  }
  const Function& function = *callee.as_function();
  if (const auto* builtin = std::get_if<BuiltinFunction>(&function.body)) {
    CallArgs call_args(CallSite{function.name, builtin->signature, expr.span}, std::move(args), budget_,
                       &sources_, &out_.time);

    return builtin->impl(call_args);
  }
  return call_user(function, std::get<UserFunction>(function.body), args, expr.span);
}

std::string def_signature(const std::string& name, const lang::DefStmt& def, const SourceTable& sources) {
  std::string s = name + "(";
  for (std::size_t i = 0; i < def.params.size(); ++i) {
    if (i) s += ", ";
    s += def.params[i].name.text;
    if (def.params[i].default_value) s += " = " + span_text(sources, def.params[i].default_value->span);
  }
  return s + ")";
}

std::vector<int> match_def_arguments(const CallSite& site, const std::vector<Arg>& args,
                                     const lang::DefStmt& def) {
  std::vector<std::string_view> names;
  std::vector<bool> needed;
  for (const lang::Param& p : def.params) {
    names.push_back(p.name.text);
    needed.push_back(!p.default_value);
  }
  return match_arguments(site, args, names, needed);
}

const std::string& Evaluator::signature_of(const Function& function, const lang::DefStmt& def) {
  const auto it = signatures_.find(&def);
  if (it != signatures_.end()) return it->second;
  return signatures_.emplace(&def, def_signature(function.name, def, sources_)).first->second;
}

Value Evaluator::call_user(const Function& function, const UserFunction& user, const std::vector<Arg>& args,
                           const lang::SourceSpan& call_span) {
  const lang::DefStmt& def = *user.def;
  if (call_depth_ >= budget_.limits().calls)
    fail(call_span, limit_message("nested calls", budget_.limits().calls, "calls"),
         "does '" + function.name + "' recurse without reaching a case that returns directly?");
  const CallDepth depth(call_depth_);
  try {
    const CallSite site{function.name, signature_of(function, def), call_span};
    const std::vector<int> slots = match_def_arguments(site, args, def);

    auto local = std::make_shared<Scope>(user.closure);
    for (std::size_t i = 0; i < def.params.size(); ++i) {
      // A default is evaluated at the call, in the function's scope, after the parameters before it:
      // def f(a, b = a * 2).
      Value v = slots[i] >= 0 ? args[static_cast<std::size_t>(slots[i])].value
                              : eval(*def.params[i].default_value, local);
      local->define(def.params[i].name.text, std::move(v), def.params[i].name.span);
    }
    if (def.value) return eval(*def.value, local);
    if (run_statements(def.body->statements, local) == Flow::Return) {
      Value result = std::move(return_value_);
      return_value_ = Value();
      return result;
    }
    return Value();
  } catch (EvalError& e) {
    add_note(e, call_span, "in the call of '" + function.name + "' here");
    throw;
  }
}

}  // namespace hlr::runtime
