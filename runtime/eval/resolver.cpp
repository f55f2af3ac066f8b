#include "runtime/eval/resolver.hpp"

#include <memory>
#include <set>
#include <string>
#include <unordered_map>

#include "lang/overloaded.hpp"
#include "runtime/builtins/builtins.hpp"
#include "runtime/eval/eval_detail.hpp"
#include "runtime/eval/evaluator.hpp"

namespace hlr::runtime {

namespace {

using lang::Overloaded;

struct Declared {
  const lang::DefStmt* def = nullptr;  // set for a `def`: its calls are checked
  bool defined = false;                // reached in statement order
};

// One scope of the evaluator's, with what it declares anywhere (for function bodies) and what is
// defined so far (for the statements running in it).
struct StaticScope {
  StaticScope* parent = nullptr;
  int function_level = 0;  // how many function bodies enclose it
  std::unordered_map<std::string, Declared> names;
};

class Resolver {
 public:
  explicit Resolver(SourceTable& sources) : sources_(sources) {
    for (const char* name : {"frame", "t", "time", "frames"}) frame_globals_.names[name].defined = true;
  }

  Resolution run(const SourceEntry& main) {
    StaticScope globals{&frame_globals_, 0, {}};
    std::set<lang::FileId> seen{main.id};
    declare_all(main.script->statements, globals, seen);
    included_.insert(main.id);
    statements(main.script->statements, globals);
    return {std::move(errors_), uses_frames_};
  }

 private:
  // ---- scopes ----

  // Declares what `statements` define directly in `scope` (and what the files they include define).
  void declare_all(const std::vector<lang::Stmt>& statements, StaticScope& scope,
                   std::set<lang::FileId>& seen) {
    for (const lang::Stmt& s : statements) {
      if (const auto* let = std::get_if<lang::LetStmt>(&s.node)) scope.names.try_emplace(let->name.text);
      if (const auto* solid = std::get_if<lang::SolidStmt>(&s.node))
        scope.names.try_emplace(solid->name.text);
      if (const auto* def = std::get_if<lang::DefStmt>(&s.node)) {
        Declared& d = scope.names[def->name.text];
        if (!d.def) d.def = def;
      }
      if (const auto* include = std::get_if<lang::IncludeStmt>(&s.node))
        if (const SourceEntry* entry = load(*include); entry && seen.insert(entry->id).second)
          declare_all(entry->script->statements, scope, seen);
    }
  }

  void define(StaticScope& scope, const std::string& name, const lang::DefStmt* def = nullptr) {
    Declared& d = scope.names[name];
    d.defined = true;
    d.def = def;
  }

  // What `name` means here: the innermost binding the evaluator would find, or nullptr (a built-in, or
  // unknown). Scopes of the current function count only what is defined so far; enclosing scopes outside
  // it count everything they declare, because the body runs later.
  const Declared* lookup(const std::string& name, const StaticScope& scope) const {
    for (const StaticScope* s = &scope; s; s = s->parent) {
      const auto it = s->names.find(name);
      if (it != s->names.end() && (it->second.defined || s->function_level < scope.function_level))
        return &it->second;
    }
    return nullptr;
  }

  std::vector<std::string> visible_names(const StaticScope& scope) const {
    std::vector<std::string> out;
    for (const StaticScope* s = &scope; s; s = s->parent)
      for (const auto& [name, d] : s->names)
        if (d.defined || s->function_level < scope.function_level) out.push_back(name);
    return out;
  }

  // The included file, loaded as the evaluator loads it; nullptr when it cannot be (the evaluator says why).
  const SourceEntry* load(const lang::IncludeStmt& include) {
    if (include.path.empty()) {
      missing_include_ = true;
      return nullptr;
    }
    const IncludeTarget target = include_target(sources_, include);
    if (!target.refusal.empty()) {  // the evaluator says why
      missing_include_ = true;
      return nullptr;
    }
    std::string error;
    const SourceEntry* entry = sources_.load(target.path, target.shown, error);
    if (entry && entry->script) return entry;
    missing_include_ = true;
    return nullptr;
  }

  // ---- statements ----

  void statements(const std::vector<lang::Stmt>& list, StaticScope& scope) {
    for (const lang::Stmt& s : list) statement(s, scope);
  }

  void block(const lang::Block& b, StaticScope& parent) {
    StaticScope scope{&parent, parent.function_level, {}};
    std::set<lang::FileId> seen = included_;
    declare_all(b.statements, scope, seen);
    statements(b.statements, scope);
  }

  void options(const std::vector<lang::Argument>& args, StaticScope& scope) {
    for (const lang::Argument& a : args) expr(*a.value, scope);
  }

  void statement(const lang::Stmt& stmt, StaticScope& scope) {
    std::visit(Overloaded{
                   [&](const lang::SolidStmt& s) {
                     options(s.options, scope);
                     for (std::size_t k = 0; k < s.body.position_count(); ++k)
                       expr(s.body.position_at(k), scope);
                     define(scope, s.name.text);
                   },
                   [&](const lang::LetStmt& s) {
                     expr(*s.value, scope);
                     define(scope, s.name.text);
                   },
                   [&](const lang::DefStmt& s) {
                     define(scope, s.name.text, &s);
                     function(s, scope);
                   },
                   [&](const lang::ReturnStmt& s) { optional(s.value, scope); },
                   [&](const lang::ForStmt& s) {
                     expr(*s.iterable, scope);
                     StaticScope body{&scope, scope.function_level, {}};
                     define(body, s.variable.text);
                     std::set<lang::FileId> seen = included_;
                     declare_all(s.body.statements, body, seen);
                     statements(s.body.statements, body);
                   },
                   [&](const lang::IfStmt& s) {
                     expr(*s.condition, scope);
                     block(s.then_block, scope);
                     if (s.else_block) block(*s.else_block, scope);
                   },
                   [&](const lang::DrawStmt& s) {
                     expr(*s.object, scope);
                     optional(s.transform, scope);
                     if (s.pen) expr(*s.pen->number, scope);
                   },
                   [&](const lang::CameraStmt& s) {
                     expr(*s.value, scope);
                     cameras_.insert(s.name.text);
                   },
                   [&](const lang::AnimateStmt& s) {
                     expr(*s.frames, scope);
                     optional(s.fps, scope);
                   },
                   [&](const lang::OutputStmt& s) {
                     expr(*s.pattern, scope);
                     options(s.paper.options, scope);
                   },
                   [&](const lang::PaperStmt& s) { options(s.paper.options, scope); },
                   [&](const lang::StyleStmt& s) {
                     optional(s.levels, scope);
                     if (s.pen) expr(*s.pen->number, scope);
                   },
                   [&](const lang::IncludeStmt& s) {
                     // As the evaluator: each file once, its statements in the including scope.
                     const SourceEntry* entry = load(s);
                     if (!entry || !included_.insert(entry->id).second) return;
                     statements(entry->script->statements, scope);
                   },
                   [&](const lang::PenStmt& s) {
                     expr(*s.number, scope);
                     options(s.options, scope);
                   },
                   [&](const lang::PlotterStmt& s) { options(s.entries, scope); },
                   [&](const lang::ViewsStmt& s) {
                     expr(*s.object, scope);
                     options(s.options, scope);
                   },
                   [&](const lang::ViewStmt& s) {
                     // A bare name may be a camera declared before (the evaluator looks there when the
                     // name is bound to nothing).
                     const auto* ref = std::get_if<lang::NameRef>(&s.camera->node);
                     if (!ref || lookup(ref->name, scope) || !cameras_.count(ref->name))
                       expr(*s.camera, scope);
                     expr(*s.point, scope);
                     options(s.options, scope);
                   },
                   [&](const lang::DimensionStmt& s) {
                     if (s.vertex) expr(*s.vertex, scope);
                     expr(*s.from, scope);
                     expr(*s.to, scope);
                     options(s.options, scope);
                   },
                   [&](const lang::LabelStmt& s) {
                     expr(*s.text, scope);
                     expr(*s.point, scope);
                     if (s.size) expr(*s.size, scope);
                     if (s.pen) expr(*s.pen->number, scope);
                   },
               },
               stmt.node);
  }

  // A def's body, as its calls will run it: parameters in order (a default sees the ones before it),
  // then the body in the same scope.
  void function(const lang::DefStmt& def, StaticScope& closure) {
    StaticScope local{&closure, closure.function_level + 1, {}};
    if (def.body) {
      std::set<lang::FileId> seen = included_;
      declare_all(def.body->statements, local, seen);
    }
    for (const lang::Param& p : def.params) {
      optional(p.default_value, local);
      define(local, p.name.text);
    }
    if (def.value) expr(*def.value, local);
    if (def.body) statements(def.body->statements, local);
  }

  // ---- expressions ----

  void optional(const lang::ExprPtr& e, StaticScope& scope) {
    if (e) expr(*e, scope);
  }

  void expr(const lang::Expr& e, StaticScope& scope) {
    std::visit(Overloaded{
                   [&](const lang::NumberLit&) {},
                   [&](const lang::BoolLit&) {},
                   [&](const lang::StringLit& s) {
                     for (const lang::StringPart& part : s.parts) optional(part.expr, scope);
                   },
                   [&](const lang::VectorLit& v) {
                     for (const lang::ExprPtr& c : v.components) optional(c, scope);
                   },
                   [&](const lang::ListLit& l) {
                     for (const lang::ExprPtr& item : l.items) expr(*item, scope);
                   },
                   [&](const lang::ListComprehension& c) {
                     expr(*c.iterable, scope);
                     StaticScope item{&scope, scope.function_level, {}};
                     define(item, c.variable->text);
                     optional(c.condition, item);
                     expr(*c.element, item);
                   },
                   [&](const lang::NameRef& n) { name(n, e, scope); },
                   [&](const lang::UnaryExpr& u) { expr(*u.operand, scope); },
                   [&](const lang::BinaryExpr& b) {
                     expr(*b.lhs, scope);
                     expr(*b.rhs, scope);
                   },
                   [&](const lang::CallExpr& c) { call(c, e, scope); },
                   [&](const lang::MemberExpr& m) { expr(*m.object, scope); },
                   [&](const lang::IndexExpr& i) {
                     expr(*i.object, scope);
                     expr(*i.index, scope);
                   },
               },
               e.node);
  }

  void name(const lang::NameRef& ref, const lang::Expr& e, const StaticScope& scope) {
    if (const Declared* d = lookup(ref.name, scope)) {
      uses_frames_ = uses_frames_ || d == &frame_globals_.names.at("frames");
      return;
    }
    // A file that cannot be included may define it; the evaluator reports that file instead.
    if (builtins().find(ref.name) || missing_include_) return;
    if (!unknown_.insert(ref.name).second) return;  // one report per name: its first use
    std::vector<std::string> candidates = visible_names(scope);
    const std::vector<std::string> builtin_names = builtins().names();
    candidates.insert(candidates.end(), builtin_names.begin(), builtin_names.end());
    std::string hint = did_you_mean(ref.name, candidates);
    if (hint.empty())
      hint = "define it first with 'let " + ref.name + " = ...' or 'def " + ref.name + "(...)'";
    report(e.span, "unknown name '" + ref.name + "'", hint);
  }

  void call(const lang::CallExpr& c, const lang::Expr& e, StaticScope& scope) {
    expr(*c.callee, scope);
    for (const lang::Argument& a : c.args) expr(*a.value, scope);
    const auto* ref = std::get_if<lang::NameRef>(&c.callee->node);
    if (!ref) return;
    std::vector<Arg> args;
    for (const lang::Argument& a : c.args) {
      Arg arg;
      if (a.label) {
        arg.label = a.label->text;
        arg.label_span = a.label->span;
      }
      arg.span = a.value->span;
      args.push_back(std::move(arg));
    }
    if (const Declared* d = lookup(ref->name, scope)) {
      if (!d->def) return;  // a value known only when it runs
      const std::string signature = def_signature(ref->name, *d->def, sources_);
      attempt([&] { match_def_arguments(CallSite{ref->name, signature, e.span}, args, *d->def); });
      return;
    }
    const Value* builtin = builtins().find(ref->name);
    if (!builtin) return;  // reported as an unknown name
    if (!builtin->is(ValueKind::Function)) {
      report(c.callee->span,
             "'" + ref->name + "' is " + kind_with_article(builtin->kind()) + ", not a function");
      return;
    }
    const auto* b = std::get_if<BuiltinFunction>(&builtin->as_function()->body);
    if (!b || b->forms.empty()) return;
    const CallSite site{ref->name, b->signature, e.span};
    // Accepted when some form takes the arguments; otherwise the error of the form that knows the most
    // of the names given (the one the implementation would pick by them).
    std::size_t best = 0, best_known = 0;
    for (std::size_t f = 0; f < b->forms.size(); ++f) {
      std::size_t known = 0;
      for (const Arg& a : args)
        for (const Param& p : *b->forms[f]) known += !a.label.empty() && p.name == a.label;
      if (known > best_known) best = f, best_known = known;
      try {
        bind_form(site, args, *b->forms[f]);
        return;
      } catch (const EvalError&) {
      }
    }
    attempt([&] { bind_form(site, args, *b->forms[best]); });
  }

  static void bind_form(const CallSite& site, const std::vector<Arg>& args, const ParamList& form) {
    std::vector<std::string_view> names;
    std::vector<bool> needed;
    for (const Param& p : form) {
      names.push_back(p.name);
      needed.push_back(p.required);
    }
    match_arguments(site, args, names, needed);
  }

  template <typename Check>
  void attempt(Check&& check) {
    try {
      check();
    } catch (EvalError& error) {
      for (lang::Diagnostic& d : error.diagnostics) errors_.push_back(std::move(d));
    }
  }

  void report(const lang::SourceSpan& span, std::string message, std::string hint = {}) {
    lang::Diagnostic d;
    d.span = span;
    d.message = std::move(message);
    d.hint = std::move(hint);
    errors_.push_back(std::move(d));
  }

  SourceTable& sources_;
  StaticScope frame_globals_;
  bool uses_frames_ = false;
  bool missing_include_ = false;     // an include that cannot be read or parsed: names may come from it
  std::set<std::string> unknown_;    // names reported as unknown
  std::set<std::string> cameras_;    // declared by camera statements so far: a view may name one
  std::set<lang::FileId> included_;  // files whose statements were walked, each once as the evaluator does
  std::vector<lang::Diagnostic> errors_;
};

}  // namespace

Resolution resolve_program(const SourceEntry& main, SourceTable& sources) {
  if (!main.script) return {};
  return Resolver(sources).run(main);
}

}  // namespace hlr::runtime
