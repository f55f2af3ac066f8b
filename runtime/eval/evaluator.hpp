// The tree-walking evaluator: runs a parsed script once, for one frame, and fills a FrameScene.
//   statements  evaluator.cpp (let def return for if draw camera), eval_settings.cpp (animate output
//               style include), eval_devices.cpp (paper pen plotter, pen numbers), eval_solid.cpp (solid)
//   expressions eval_expr.cpp, operators.cpp; calls eval_call.cpp
// Scopes: builtins (looked up last) ← frame globals (frame, t, time) ← the script's top level ← blocks.
// Every error is an EvalError at a span; the evaluator never prints or exits.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "lang/ast.hpp"
#include "runtime/base/source_table.hpp"
#include "runtime/eval/frame_scene.hpp"
#include "runtime/values/arguments.hpp"
#include "runtime/values/budget.hpp"
#include "runtime/values/function.hpp"
#include "runtime/values/scope.hpp"
#include "runtime/values/value.hpp"

namespace hlr::runtime {

// The file an `include` statement names, and how messages show it. `refusal` (with `hint`) says why the
// script may not read it (file_access.hpp; also a file that is not a script): then it is never opened.
struct IncludeTarget {
  std::filesystem::path path;
  std::string shown;
  bool library = false;  // "std/NAME.hls"
  std::string refusal, hint;
  ErrorKind refusal_kind = ErrorKind::Denied;
};
IncludeTarget include_target(const SourceTable& sources, const lang::IncludeStmt& include);

class Evaluator {
 public:
  Evaluator(SourceTable& sources, FrameScene& out, const Limits& limits = {});
  ~Evaluator();  // clears the scopes closures point into, breaking their reference cycles
  Evaluator(const Evaluator&) = delete;
  Evaluator& operator=(const Evaluator&) = delete;

  // Runs a parsed file at the top level (the file must have parsed without errors).
  void run(const SourceEntry& file);
  // Evaluates one expression in the top-level scope (tests, the REPL).
  Value evaluate(const lang::Expr& expr);
  // A top-level name's value after run(), or nullptr.
  const Value* global(const std::string& name) const;

  const Budget& budget() const { return budget_; }

 private:
  enum class Flow { Next, Return };

  // statements
  Flow run_statements(const std::vector<lang::Stmt>& statements, const ScopePtr& scope);
  Flow run_block(const lang::Block& block, const ScopePtr& parent);
  Flow exec(const lang::Stmt& stmt, const ScopePtr& scope);
  void exec_def(const lang::DefStmt& def, const ScopePtr& scope);
  Flow exec_for(const lang::ForStmt& loop, const ScopePtr& scope);
  Flow exec_if(const lang::IfStmt& branch, const ScopePtr& scope);
  void exec_draw(const lang::DrawStmt& draw, const ScopePtr& scope);
  // What `draw OBJECT at T pen N` adds, added to `scene` (names numbered frame-wide, "box#2").
  void add_to_scene(const Value& object, const Affine3& at, const lang::SourceSpan& object_span,
                    const lang::SourceSpan& span, int pen, Scene& scene, std::vector<int>& pens);
  void exec_camera(const lang::CameraStmt& camera, const lang::Stmt& stmt, const ScopePtr& scope);
  void exec_solid(const lang::SolidStmt& solid, const ScopePtr& scope);  // eval_solid.cpp
  // settings (eval_settings.cpp)
  void exec_animate(const lang::AnimateStmt& animate, const lang::Stmt& stmt, const ScopePtr& scope);
  void exec_output(const lang::OutputStmt& output, const lang::Stmt& stmt, const ScopePtr& scope);
  void exec_style(const lang::StyleStmt& style, const lang::Stmt& stmt, const ScopePtr& scope);
  void exec_include(const lang::IncludeStmt& include, const ScopePtr& scope);
  // A setting given a second time: an error at `span` pointing at the first.
  [[noreturn]] static void already_set(const lang::SourceSpan& span, const std::string& what,
                                       const lang::SourceSpan& first);
  // device settings (eval_devices.cpp)
  void set_paper(const lang::PaperSpec& paper, const lang::Stmt& stmt, const ScopePtr& scope);
  void exec_pen(const lang::PenStmt& pen, const lang::Stmt& stmt, const ScopePtr& scope);
  void exec_plotter(const lang::PlotterStmt& plotter, const lang::Stmt& stmt, const ScopePtr& scope);
  void exec_label(const lang::LabelStmt& label, const lang::Stmt& stmt, const ScopePtr& scope);
  void exec_views(const lang::ViewsStmt& views, const lang::Stmt& stmt, const ScopePtr& scope);
  void check_new_view(const std::string& name, const lang::SourceSpan& span) const;
  void exec_view(const lang::ViewStmt& view, const lang::Stmt& stmt,
                 const ScopePtr& scope);  // eval_views.cpp
  void exec_dimension(const lang::DimensionStmt& dimension, const lang::Stmt& stmt, const ScopePtr& scope);
  // `pen N`: a whole number from 1 to 255, else an error at `expr`
  int eval_pen_number(const lang::Expr& expr, const ScopePtr& scope);

  // expressions (eval_expr.cpp)
  Value eval(const lang::Expr& expr, const ScopePtr& scope);
  Value eval_comprehension(const lang::ListComprehension& comp, const lang::Expr& expr,
                           const ScopePtr& scope);
  Value eval_name(const lang::NameRef& ref, const lang::Expr& expr, const ScopePtr& scope);
  Value eval_string(const lang::StringLit& lit, const ScopePtr& scope);
  Value eval_binary(const lang::BinaryExpr& bin, const lang::Expr& expr, const ScopePtr& scope);
  Value eval_member(const lang::MemberExpr& member, const ScopePtr& scope);
  Value eval_index(const lang::IndexExpr& index, const ScopePtr& scope);
  // a value that must be a number / bool / transform, else an error naming `what`
  double eval_number(const lang::Expr& expr, const ScopePtr& scope, const std::string& what);

  // calls (eval_call.cpp)
  Value eval_call(const lang::CallExpr& call, const lang::Expr& expr, const ScopePtr& scope);
  Value call_user(const Function& function, const UserFunction& user, const std::vector<Arg>& args,
                  const lang::SourceSpan& call_span);
  const std::string& signature_of(const Function& function, const lang::DefStmt& def);

  // Binds a new name; defining a name twice in one scope is an error.
  void define(const ScopePtr& scope, const lang::Name& name, Value value);
  std::string source_text(const lang::SourceSpan& span) const;

  SourceTable& sources_;
  FrameScene& out_;
  Budget budget_;
  ScopePtr globals_;                              // the script's top level (its parent binds frame, t, time)
  std::vector<std::weak_ptr<Scope>> def_scopes_;  // scopes a `def` ran in (see ~Evaluator)
  std::size_t def_scopes_pruned_at_ = 64;
  std::size_t call_depth_ = 0;
  std::size_t eval_depth_ = 0;  // native recursion, bounded by kMaxEvalDepth
  Value return_value_;
  std::vector<lang::FileId> include_stack_;
  std::set<lang::FileId> included_;
  std::unordered_map<std::string, int> drawn_names_;  // name → times drawn, for "box#2"
  std::unordered_map<const lang::DefStmt*, std::string> signatures_;
};

}  // namespace hlr::runtime
