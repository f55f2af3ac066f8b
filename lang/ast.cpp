// Names of operators and S-expression dumps of the AST (tests, REPL `:ast`, debugging).
#include "lang/ast.hpp"

#include <charconv>
#include <cmath>
#include <iterator>
#include <span>
#include <string>

#include "lang/overloaded.hpp"

namespace hlr::lang {

const char* to_string(UnaryOp op) { return op == UnaryOp::Negate ? "-" : "not"; }

const char* to_string(BinaryOp op) {
  switch (op) {
    case BinaryOp::Then:
      return "then";
    case BinaryOp::Or:
      return "or";
    case BinaryOp::And:
      return "and";
    case BinaryOp::Eq:
      return "==";
    case BinaryOp::Ne:
      return "!=";
    case BinaryOp::Lt:
      return "<";
    case BinaryOp::Le:
      return "<=";
    case BinaryOp::Gt:
      return ">";
    case BinaryOp::Ge:
      return ">=";
    case BinaryOp::Range:
      return "..";
    case BinaryOp::Add:
      return "+";
    case BinaryOp::Sub:
      return "-";
    case BinaryOp::Mul:
      return "*";
    case BinaryOp::Div:
      return "/";
    case BinaryOp::Mod:
      return "%";
  }
  return "?";
}

namespace {

std::string number_text(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

std::string ids_text(const SolidBody& body, std::span<const std::uint32_t> ids) {
  std::string out;
  for (const std::uint32_t id : ids) out += " " + std::string(body.id(id));
  return out;
}

std::string block_text(const Block& block) {
  std::string out = "(block";
  for (const auto& stmt : block.statements) out += " " + dump(stmt);
  return out + ")";
}

// " a k:v ..." for call arguments, solid, paper and pen options, plotter entries.
std::string arguments_text(const std::vector<Argument>& args) {
  std::string out;
  for (const auto& arg : args) out += " " + (arg.label ? arg.label->text + ":" : "") + dump(*arg.value);
  return out;
}

std::string paper_text(const PaperSpec& paper) {
  std::string out;
  if (paper.size) out += " " + paper.size->text;
  if (paper.orientation == Orientation::Landscape) out += " landscape";
  if (paper.orientation == Orientation::Portrait) out += " portrait";
  if (!paper.options.empty()) out += " (options" + arguments_text(paper.options) + ")";
  return out;
}

std::string pen_text(const std::optional<PenClause>& pen) { return pen ? " pen " + dump(*pen->number) : ""; }

// The items in the order written, each as an S-expression.
std::string body_text(const SolidBody& body) {
  std::string out;
  std::size_t vertex = 0, face = 0, line = 0;
  for (const SolidBody::Item& item : body.items()) {
    switch (item.kind) {
      case SolidBody::ItemKind::Vertex: {
        const SolidBody::Vertex& v = body.vertices()[vertex++];
        out += " (vertex " + std::string(body.id(v.id)) + " ";
        if (v.position != SolidBody::kLiteral) {
          out += dump(body.position(v)) + ")";
          break;
        }
        // As the expression would print: a minus is a negation.
        out += "(vec";
        for (const double c : v.at)
          out += std::signbit(c) ? " (- " + number_text(-c) + ")" : " " + number_text(c);
        out += "))";
        break;
      }
      case SolidBody::ItemKind::Face: {
        out += " (face" + ids_text(body, body.ring(face, 0));
        for (std::size_t r = 1; r < body.ring_count(face); ++r)
          out += " (hole" + ids_text(body, body.ring(face, r)) + ")";
        out += ")";
        ++face;
        break;
      }
      case SolidBody::ItemKind::Line: {
        const auto& [from, to] = body.lines()[line++];
        out += " (line " + std::string(body.id(from)) + " " + std::string(body.id(to)) + ")";
        break;
      }
    }
  }
  return out;
}

}  // namespace

std::string dump(const Expr& expr) {
  return std::visit(
      Overloaded{
          [](const NumberLit& n) { return number_text(n.value); },
          [](const BoolLit& b) { return std::string(b.value ? "true" : "false"); },
          [](const StringLit& s) {
            if (s.is_plain()) return quoted(s.plain_text());
            std::string out = "(str";
            for (const auto& part : s.parts) {
              if (!part.expr) {
                out += " " + quoted(part.text);
              } else {
                out += " (fmt " + dump(*part.expr) + (part.format.empty() ? "" : " " + quoted(part.format)) +
                       ")";
              }
            }
            return out + ")";
          },
          [](const VectorLit& v) {
            return "(vec " + dump(*v.components[0]) + " " + dump(*v.components[1]) + " " +
                   dump(*v.components[2]) + ")";
          },
          [](const ListLit& l) {
            std::string out = "(list";
            for (const auto& item : l.items) out += " " + dump(*item);
            return out + ")";
          },
          [](const ListComprehension& c) {
            return "(comp " + dump(*c.element) + " for " + c.variable->text + " in " + dump(*c.iterable) +
                   (c.condition ? " if " + dump(*c.condition) : "") + ")";
          },
          [](const NameRef& n) { return n.name; },
          [](const UnaryExpr& u) {
            return std::string("(") + to_string(u.op) + " " + dump(*u.operand) + ")";
          },
          [](const BinaryExpr& b) {
            return std::string("(") + to_string(b.op) + " " + dump(*b.lhs) + " " + dump(*b.rhs) + ")";
          },
          [](const CallExpr& c) { return "(call " + dump(*c.callee) + arguments_text(c.args) + ")"; },
          [](const MemberExpr& m) { return "(. " + dump(*m.object) + " " + m.member->text + ")"; },
          [](const IndexExpr& i) { return "(index " + dump(*i.object) + " " + dump(*i.index) + ")"; },
      },
      expr.node);
}

std::string dump(const Stmt& stmt) {
  return std::visit(
      Overloaded{
          [](const SolidStmt& s) {
            std::string out = "(solid " + s.name.text;
            if (!s.options.empty()) out += " (options" + arguments_text(s.options) + ")";
            out += body_text(s.body);
            return out + ")";
          },
          [](const LetStmt& s) { return "(let " + s.name.text + " " + dump(*s.value) + ")"; },
          [](const DefStmt& s) {
            std::string out = "(def " + s.name.text + " (";
            for (std::size_t i = 0; i < s.params.size(); ++i) {
              out += (i ? " " : "") + s.params[i].name.text;
              if (s.params[i].default_value) out += "=" + dump(*s.params[i].default_value);
            }
            out += ") ";
            return out + (s.body ? block_text(*s.body) : dump(*s.value)) + ")";
          },
          [](const ReturnStmt& s) {
            return s.value ? "(return " + dump(*s.value) + ")" : std::string("(return)");
          },
          [](const ForStmt& s) {
            return "(for " + s.variable.text + " " + dump(*s.iterable) + " " + block_text(s.body) + ")";
          },
          [](const IfStmt& s) {
            std::string out = "(if " + dump(*s.condition) + " " + block_text(s.then_block);
            if (s.else_block) out += " " + block_text(*s.else_block);
            return out + ")";
          },
          [](const DrawStmt& s) {
            return "(draw " + dump(*s.object) + (s.transform ? " at " + dump(*s.transform) : "") +
                   pen_text(s.pen) + ")";
          },
          [](const CameraStmt& s) { return "(camera " + s.name.text + " " + dump(*s.value) + ")"; },
          [](const AnimateStmt& s) {
            return "(animate " + dump(*s.frames) + (s.fps ? " fps " + dump(*s.fps) : "") + ")";
          },
          [](const OutputStmt& s) {
            return "(output " + dump(*s.pattern) + paper_text(s.paper) +
                   (s.plotter ? " plotter " + s.plotter->text : "") + ")";
          },
          [](const PaperStmt& s) { return "(paper" + paper_text(s.paper) + ")"; },
          [](const StyleStmt& s) {
            return "(style " + s.property.text + " " + s.value.text +
                   (s.levels ? " " + dump(*s.levels) : "") + pen_text(s.pen) + ")";
          },
          [](const IncludeStmt& s) { return "(include " + quoted(s.path) + ")"; },
          [](const PenStmt& s) {
            return "(pen " + dump(*s.number) + " (options" + arguments_text(s.options) + "))";
          },
          [](const LabelStmt& s) {
            return "(label " + dump(*s.text) + (s.on_page ? " at page " : " at ") + dump(*s.point) +
                   (s.size ? " size " + dump(*s.size) : "") + pen_text(s.pen) + ")";
          },
          [](const PlotterStmt& s) {
            return "(plotter " + s.name.text + " (entries" + arguments_text(s.entries) + "))";
          },
          [](const DimensionStmt& s) {
            return "(dimension " + (s.vertex ? "angle " + dump(*s.vertex) + " " : std::string()) +
                   dump(*s.from) + " " + dump(*s.to) + (s.view ? " in " + s.view->text : "") + " (options" +
                   arguments_text(s.options) + "))";
          },
          [](const ViewsStmt& s) {
            return "(views " + dump(*s.object) + " (options" + arguments_text(s.options) + "))";
          },
          [](const ViewStmt& s) {
            return "(view " + s.name.text + " " + dump(*s.camera) + " at page " + dump(*s.point) +
                   " (options" + arguments_text(s.options) + "))";
          },
      },
      stmt.node);
}

std::string dump(const Script& script) {
  std::string out;
  for (const auto& stmt : script.statements) out += dump(stmt) + "\n";
  return out;
}

const char* statement_keyword(const Stmt& stmt) {
  static constexpr const char* names[] = {
      "solid", "let",   "def",     "return", "for",     "if",    "draw", "camera", "animate",  "output",
      "paper", "style", "include", "pen",    "plotter", "label", "view", "views",  "dimension"};
  static_assert(std::size(names) == std::variant_size_v<decltype(Stmt::node)>);
  return names[stmt.node.index()];
}

}  // namespace hlr::lang
