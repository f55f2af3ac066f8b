// Statements: let, def, return, for, if, draw, camera; the scope and closure bookkeeping.
#include "runtime/eval/evaluator.hpp"

#include <cmath>
#include <stdexcept>

#include "lang/overloaded.hpp"
#include "runtime/builtins/solid_cache.hpp"
#include "runtime/eval/eval_detail.hpp"
#include "runtime/values/placement.hpp"

namespace hlr::runtime {

namespace {

using lang::Overloaded;

bool is_identity(const Affine3& a) {
  const Affine3 id;
  return a.m == id.m && a.t == id.t;
}

}  // namespace

Evaluator::Evaluator(SourceTable& sources, FrameScene& out, const Limits& limits)
    : sources_(sources), out_(out), budget_(limits) {
  auto frame_globals = std::make_shared<Scope>();
  frame_globals->define("frame", Value::number(out.time.frame), {});
  frame_globals->define("t", Value::number(out.time.t), {});
  frame_globals->define("time", Value::number(out.time.time), {});
  frame_globals->define("frames", Value::number(out.time.frames), {});
  globals_ = std::make_shared<Scope>(std::move(frame_globals));
  def_scopes_.push_back(globals_);
}

Evaluator::~Evaluator() {
  for (const auto& weak : def_scopes_)
    if (const ScopePtr scope = weak.lock()) scope->clear();
}

void Evaluator::run(const SourceEntry& file) {
  include_stack_.push_back(file.id);
  included_.insert(file.id);
  run_statements(file.script->statements, globals_);
  include_stack_.pop_back();
  for (lang::Diagnostic& w : budget_.take_warnings()) out_.warnings.push_back(std::move(w));
  out_.steps = budget_.steps();
  out_.faces_built = budget_.faces_built();
}

Value Evaluator::evaluate(const lang::Expr& expr) { return eval(expr, globals_); }

const Value* Evaluator::global(const std::string& name) const {
  const Binding* b = globals_->find(name);
  return b ? &b->value : nullptr;
}

void Evaluator::define(const ScopePtr& scope, const lang::Name& name, Value value) {
  if (const Binding* existing = scope->find_local(name.text)) {
    lang::Diagnostic d;
    d.span = name.span;
    d.message = "'" + name.text + "' is already defined in this scope";
    d.hint = "names cannot be rebound; choose another name (an inner block or function may shadow it)";
    if (existing->span.end > 0) d.notes.push_back({existing->span, "'" + name.text + "' was defined here"});
    throw EvalError(std::move(d));
  }
  scope->define(name.text, std::move(value), name.span);
}

std::string Evaluator::source_text(const lang::SourceSpan& span) const { return span_text(sources_, span); }

Evaluator::Flow Evaluator::run_statements(const std::vector<lang::Stmt>& statements, const ScopePtr& scope) {
  for (const lang::Stmt& s : statements)
    if (exec(s, scope) == Flow::Return) return Flow::Return;
  return Flow::Next;
}

Evaluator::Flow Evaluator::run_block(const lang::Block& block, const ScopePtr& parent) {
  return run_statements(block.statements, std::make_shared<Scope>(parent));
}

Evaluator::Flow Evaluator::exec(const lang::Stmt& stmt, const ScopePtr& scope) {
  const DepthGuard guard(eval_depth_, stmt.span);
  budget_.step(stmt.span);
  return std::visit(
      Overloaded{
          [&](const lang::SolidStmt& s) { return exec_solid(s, scope), Flow::Next; },
          [&](const lang::LetStmt& s) { return define(scope, s.name, eval(*s.value, scope)), Flow::Next; },
          [&](const lang::DefStmt& s) { return exec_def(s, scope), Flow::Next; },
          [&](const lang::ReturnStmt& s) {
            return_value_ = s.value ? eval(*s.value, scope) : Value();
            return Flow::Return;
          },
          [&](const lang::ForStmt& s) { return exec_for(s, scope); },
          [&](const lang::IfStmt& s) { return exec_if(s, scope); },
          [&](const lang::DrawStmt& s) { return exec_draw(s, scope), Flow::Next; },
          [&](const lang::CameraStmt& s) { return exec_camera(s, stmt, scope), Flow::Next; },
          [&](const lang::AnimateStmt& s) { return exec_animate(s, stmt, scope), Flow::Next; },
          [&](const lang::OutputStmt& s) { return exec_output(s, stmt, scope), Flow::Next; },
          [&](const lang::PaperStmt& s) { return set_paper(s.paper, stmt, scope), Flow::Next; },
          [&](const lang::StyleStmt& s) { return exec_style(s, stmt, scope), Flow::Next; },
          [&](const lang::IncludeStmt& s) { return exec_include(s, scope), Flow::Next; },
          [&](const lang::PenStmt& s) { return exec_pen(s, stmt, scope), Flow::Next; },
          [&](const lang::PlotterStmt& s) { return exec_plotter(s, stmt, scope), Flow::Next; },
          [&](const lang::LabelStmt& s) { return exec_label(s, stmt, scope), Flow::Next; },
          [&](const lang::ViewStmt& s) { return exec_view(s, stmt, scope), Flow::Next; },
          [&](const lang::ViewsStmt& s) { return exec_views(s, stmt, scope), Flow::Next; },
          [&](const lang::DimensionStmt& s) { return exec_dimension(s, stmt, scope), Flow::Next; },
      },
      stmt.node);
}

void Evaluator::exec_def(const lang::DefStmt& def, const ScopePtr& scope) {
  auto function = std::make_shared<Function>();
  function->name = def.name.text;
  function->body = UserFunction{&def, scope};
  define(scope, def.name, Value::function(std::move(function)));
  // The closure now points at `scope`, which holds it: remember the scope so ~Evaluator can break the
  // cycle. Forget scopes that died meanwhile, so a def inside a long loop does not grow the list; a run
  // of defs in one scope (15 000 at the top level of a generated script) is one entry, not one each,
  // or ~Evaluator would clear that scope's table again for every def.
  const bool known = !def_scopes_.empty() && !def_scopes_.back().owner_before(scope) &&
                     !scope.owner_before(def_scopes_.back());
  if (!known) def_scopes_.push_back(scope);
  if (def_scopes_.size() >= 2 * def_scopes_pruned_at_) {
    std::erase_if(def_scopes_, [](const std::weak_ptr<Scope>& w) { return w.expired(); });
    def_scopes_pruned_at_ = std::max<std::size_t>(64, def_scopes_.size());
  }
}

Evaluator::Flow Evaluator::exec_for(const lang::ForStmt& loop, const ScopePtr& scope) {
  const Value items = eval(*loop.iterable, scope);
  if (!items.is_sequence())
    fail(loop.iterable->span, "'for' needs a list or a range to walk, got " + kind_with_article(items.kind()),
         "for example: for i in 0..4 { ... } or for p in [(0, 0, 0), (1, 0, 0)] { ... }");
  const std::size_t n = sequence_size(items);
  for (std::size_t i = 0; i < n; ++i) {
    auto body = std::make_shared<Scope>(scope);  // one scope per iteration: closures keep their own item
    body->define(loop.variable.text, sequence_item(items, i), loop.variable.span);
    if (run_statements(loop.body.statements, body) == Flow::Return) return Flow::Return;
  }
  return Flow::Next;
}

Evaluator::Flow Evaluator::exec_if(const lang::IfStmt& branch, const ScopePtr& scope) {
  const Value condition = eval(*branch.condition, scope);
  if (!condition.is(ValueKind::Bool))
    fail(branch.condition->span, "'if' needs a bool condition, got " + kind_with_article(condition.kind()),
         "compare explicitly, e.g. if n != 0 { ... }");
  if (condition.as_bool()) return run_block(branch.then_block, scope);
  if (branch.else_block) return run_block(*branch.else_block, scope);
  return Flow::Next;
}

void Evaluator::exec_draw(const lang::DrawStmt& draw, const ScopePtr& scope) {
  if (!out_.first_draw) out_.first_draw = draw.object->span;
  const Value object = eval(*draw.object, scope);
  Affine3 at;
  if (draw.transform) {
    const Value t = eval(*draw.transform, scope);
    if (!t.is(ValueKind::Transform))
      fail(draw.transform->span, "'draw ... at' needs a transform, got " + kind_with_article(t.kind()),
           "for example: draw s at translate(1, 0, 0) then rotate(z: 30)");
    at = t.as_transform();
  }
  // Every object this draw adds gets the pen; FrameScene::object_pens stays parallel to the objects.
  const int pen = draw.pen ? eval_pen_number(*draw.pen->number, scope) : 1;
  const lang::SourceSpan& span = draw.transform ? draw.transform->span : draw.object->span;
  add_to_scene(object, at, draw.object->span, span, pen, out_.scene, out_.object_pens);
}

void Evaluator::add_to_scene(const Value& object, const Affine3& at, const lang::SourceSpan& object_span,
                             const lang::SourceSpan& span, int pen, Scene& scene, std::vector<int>& pens) {
  for (PlacedSolid& placed : flatten_placed(object, at, object_span, "draw", budget_)) {
    budget_.charge_faces_drawn(object_span, placed.solid->faces.size(), placed.solid->vertices.size());
    SceneObject o;
    const int seen = ++drawn_names_[placed.name];
    o.name = seen == 1 ? placed.name : placed.name + "#" + std::to_string(seen);
    if (is_identity(placed.worldFromObject)) {
      o.solid = placed.solid;
    } else {
      const double det = placed.worldFromObject.determinant();
      if (det == 0 || !std::isfinite(det))
        fail(span, "the transform is singular: it would flatten the solid");
      // Checked when made: a cached placement was checked then.
      o.solid = SolidCache::shared().placed(placed.solid, placed.worldFromObject, [&] {
        auto moved = std::make_shared<const Solid>(placed.solid->transformed(placed.worldFromObject));
        for (const Point3& p : moved->vertices)
          if (!is_finite(p))
            fail(span, "the transform moves a vertex beyond the largest number (about 1.8e308)");
        return moved;
      });
    }
    scene.objects.push_back(std::move(o));
    pens.push_back(pen);
  }
}

void Evaluator::exec_camera(const lang::CameraStmt& camera, const lang::Stmt& stmt, const ScopePtr& scope) {
  const Value value = eval(*camera.value, scope);
  if (!value.is(ValueKind::Camera))
    fail(camera.value->span,
         "'camera " + camera.name.text + " =' needs a camera, got " + kind_with_article(value.kind()),
         "for example: camera " + camera.name.text + " = lookat(eye: (30, 20, 15), target: (0, 0, 0))");
  for (const NamedCamera& c : out_.cameras)
    if (c.name == camera.name.text) {
      lang::Diagnostic d;
      d.span = camera.name.span;
      d.message = "camera '" + camera.name.text + "' is already declared";
      d.hint = "give each camera its own name";
      d.notes.push_back({c.span, "the first 'camera " + c.name + "' is here"});
      throw EvalError(std::move(d));
    }
  out_.cameras.push_back({camera.name.text, value.as_camera(), stmt.span});
}

}  // namespace hlr::runtime
