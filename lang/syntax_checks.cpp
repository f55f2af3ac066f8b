// Static checks that the grammar cannot express neatly but that need no evaluation: where `return`
// may stand, the order and uniqueness of arguments and parameters, a pen only on dashed hidden lines.
// Names, arity and types are the runtime checker's business.
#include <algorithm>
#include <set>
#include <string>

#include "lang/parser.hpp"

namespace hlr::lang {
namespace {

class Checker {
 public:
  explicit Checker(std::vector<Diagnostic>& out) : out_(out) {}

  void block(const std::vector<Stmt>& statements) {
    for (const auto& stmt : statements) statement(stmt);
  }

 private:
  void error(const SourceSpan& span, std::string message, std::string hint) {
    out_.push_back({Severity::Error, span, std::move(message), std::move(hint), {}});
  }

  void statement(const Stmt& stmt) {
    std::visit([&](const auto& node) { visit(stmt, node); }, stmt.node);
  }

  void visit(const Stmt&, const SolidStmt& s) {
    for (const auto& option : s.options) expr(*option.value);  // names and values: the runtime's
    for (std::size_t k = 0; k < s.body.position_count(); ++k) expr(s.body.position_at(k));
  }
  void visit(const Stmt&, const LetStmt& s) { expr(*s.value); }
  void visit(const Stmt&, const DefStmt& s) {
    std::set<std::string> seen;
    const Param* defaulted = nullptr;
    for (const auto& param : s.params) {
      if (!seen.insert(param.name.text).second) {
        error(param.name.span, "parameter '" + param.name.text + "' appears twice in '" + s.name.text + "'",
              "give each parameter its own name");
        continue;
      }
      if (param.default_value) {
        defaulted = &param;
        expr(*param.default_value);
      } else if (defaulted) {
        error(param.name.span,
              "parameter '" + param.name.text + "' needs a default value, as '" + defaulted->name.text +
                  "' before it has one",
              "put the parameters with defaults last");
      }
    }
    if (s.value) expr(*s.value);
    if (s.body) {
      ++function_depth_;
      block(s.body->statements);
      --function_depth_;
    }
  }
  void visit(const Stmt& stmt, const ReturnStmt& s) {
    if (function_depth_ == 0) {
      error(stmt.span, "'return' outside a function body",
            "'return' belongs in the block of a function: 'def f(x) { return x * 2 }'");
    }
    if (s.value) expr(*s.value);
  }
  void visit(const Stmt&, const ForStmt& s) {
    expr(*s.iterable);
    block(s.body.statements);
  }
  void visit(const Stmt&, const IfStmt& s) {
    expr(*s.condition);
    block(s.then_block.statements);
    if (s.else_block) block(s.else_block->statements);
  }
  void visit(const Stmt&, const DrawStmt& s) {
    expr(*s.object);
    if (s.transform) expr(*s.transform);
    if (s.pen) expr(*s.pen->number);
  }
  void visit(const Stmt&, const CameraStmt& s) { expr(*s.value); }
  void visit(const Stmt&, const AnimateStmt& s) {
    expr(*s.frames);
    if (s.fps) expr(*s.fps);
  }
  void visit(const Stmt&, const OutputStmt& s) {
    expr(*s.pattern);
    arguments(s.paper.options);
  }
  void visit(const Stmt&, const PaperStmt& s) { arguments(s.paper.options); }
  void visit(const Stmt&, const StyleStmt& s) {
    if (s.levels) expr(*s.levels);
    if (!s.pen) return;
    if (s.value.text == "off") {
      error(s.pen->span, "a pen goes only with 'style hidden dashed' or 'style hidden levels N'",
            "hidden lines that are off are not drawn: remove the pen, or write 'style hidden dashed pen N'");
    }
    expr(*s.pen->number);
  }
  void visit(const Stmt&, const IncludeStmt&) {}
  void visit(const Stmt&, const PenStmt& s) {
    expr(*s.number);
    arguments(s.options);  // names and values: the runtime's
  }
  void visit(const Stmt&, const PlotterStmt& s) { arguments(s.entries); }
  void visit(const Stmt&, const DimensionStmt& s) {
    if (s.vertex) expr(*s.vertex);
    expr(*s.from);
    expr(*s.to);
    arguments(s.options);
  }
  void visit(const Stmt&, const ViewsStmt& s) {
    expr(*s.object);
    arguments(s.options);
  }
  void visit(const Stmt&, const ViewStmt& s) {
    expr(*s.camera);
    expr(*s.point);
    arguments(s.options);
  }
  void visit(const Stmt&, const LabelStmt& s) {
    expr(*s.text);
    expr(*s.point);
    if (s.size) expr(*s.size);
    if (s.pen) expr(*s.pen->number);
  }

  void arguments(const std::vector<Argument>& args) {
    for (const auto& arg : args) expr(*arg.value);
  }

  void expr(const Expr& e) {
    if (const auto* call = std::get_if<CallExpr>(&e.node)) {
      expr(*call->callee);
      std::set<std::string> labels;
      const Argument* named = nullptr;
      for (const auto& arg : call->args) {
        if (arg.label) {
          named = &arg;
          if (!labels.insert(arg.label->text).second) {
            error(arg.label->span, "argument '" + arg.label->text + "' is given twice", "remove one of them");
          }
        } else if (named) {
          error(arg.span, "positional argument after the named argument '" + named->label->text + "'",
                "put positional arguments first: f(1, 2, size: 3)");
        }
        expr(*arg.value);
      }
      return;
    }
    std::visit(
        [&](const auto& node) {
          using T = std::decay_t<decltype(node)>;
          if constexpr (std::is_same_v<T, StringLit>) {
            for (const auto& part : node.parts) {
              if (part.expr) expr(*part.expr);
            }
          } else if constexpr (std::is_same_v<T, VectorLit>) {
            for (const auto& c : node.components) expr(*c);
          } else if constexpr (std::is_same_v<T, ListLit>) {
            for (const auto& item : node.items) expr(*item);
          } else if constexpr (std::is_same_v<T, ListComprehension>) {
            expr(*node.element);
            expr(*node.iterable);
            if (node.condition) expr(*node.condition);
          } else if constexpr (std::is_same_v<T, UnaryExpr>) {
            expr(*node.operand);
          } else if constexpr (std::is_same_v<T, BinaryExpr>) {
            expr(*node.lhs);
            expr(*node.rhs);
          } else if constexpr (std::is_same_v<T, MemberExpr>) {
            expr(*node.object);
          } else if constexpr (std::is_same_v<T, IndexExpr>) {
            expr(*node.object);
            expr(*node.index);
          }
        },
        e.node);
  }

  std::vector<Diagnostic>& out_;
  int function_depth_ = 0;
};

}  // namespace

void check_syntax(const Script& script, std::vector<Diagnostic>& out) {
  const std::size_t first = out.size();
  Checker(out).block(script.statements);
  // Errors come out in source order.
  std::stable_sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(),
                   [](const Diagnostic& a, const Diagnostic& b) { return a.span.begin < b.span.begin; });
}

}  // namespace hlr::lang
