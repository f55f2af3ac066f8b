// The typed syntax tree of an hlrscript file. Parse once, evaluate per frame: the runtime walks these
// nodes (std::visit over `node`) and never sees text again. Every node carries the SourceSpan of its
// text, so any later error (unknown name, bad argument, non-planar face) can point at the script.
//
// Representation: one struct per construct, gathered in two closed sums, `Expr` and `Stmt`, each a
// span plus a std::variant. Children are owned (std::unique_ptr<Expr> where an Expr holds an Expr),
// so a Script is move-only and its node addresses are stable once parsing has finished: the runtime
// may keep pointers into it (function bodies) as long as it keeps the Script.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "lang/solid_body.hpp"
#include "lang/source.hpp"

namespace hlr::lang {

struct Expr;
using ExprPtr = std::unique_ptr<Expr>;

// A name as written, with its place: a declared name, a parameter, a named argument's label.
struct Name {
  std::string text;
  SourceSpan span;
};

// ---- expressions -------------------------------------------------------------------------------

struct NumberLit {
  double value = 0;
  bool integer = false;  // written without '.' or exponent: "48", not "48.0"
};
struct BoolLit {
  bool value = false;
};
// A piece of a string literal: plain text (escapes resolved) or an interpolation {expr:format}.
struct StringPart {
  std::string text;    // plain text when `expr` is null
  ExprPtr expr;        // the interpolated expression, or null
  std::string format;  // what follows ':' inside the braces ("03"), empty when absent
  SourceSpan span;
};
struct StringLit {
  std::vector<StringPart> parts;  // empty for ""; one text part for a plain string
  bool is_plain() const { return parts.empty() || (parts.size() == 1 && !parts[0].expr); }
  std::string plain_text() const { return parts.empty() ? std::string() : parts[0].text; }
};
struct VectorLit {  // (x, y, z)
  std::array<ExprPtr, 3> components;
};
struct ListLit {  // [a, b, ...]
  std::vector<ExprPtr> items;
};
// [element for variable in iterable] or [... if condition]: `variable` is bound afresh per item.
// The names below are boxed: an Expr is as large as its largest kind, and a Name (64 bytes) inline made
// every node of a script 136 bytes instead of 96.
struct ListComprehension {
  ExprPtr element;
  std::unique_ptr<Name> variable;
  ExprPtr iterable;
  ExprPtr condition;  // null without `if`
};
struct NameRef {
  std::string name;
};

enum class UnaryOp { Negate, Not };
enum class BinaryOp { Then, Or, And, Eq, Ne, Lt, Le, Gt, Ge, Range, Add, Sub, Mul, Div, Mod };

struct UnaryExpr {
  UnaryOp op;
  ExprPtr operand;
};
struct BinaryExpr {
  ExprPtr lhs;
  ExprPtr rhs;
  SourceSpan op_span;  // the operator token
  BinaryOp op;         // last: packed beside the span
};
struct Argument {
  std::unique_ptr<Name>
      label;  // `eye:` in lookat(eye: ...); null for a positional argument (boxed: most are)
  ExprPtr value;
  SourceSpan span;
};
struct CallExpr {
  ExprPtr callee;
  std::vector<Argument> args;
};
struct MemberExpr {  // v.x
  ExprPtr object;
  std::unique_ptr<Name> member;
};
struct IndexExpr {  // l[0]
  ExprPtr object;
  ExprPtr index;
};

// Expressions are at most kMaxExprHeight nodes deep (the parser reports deeper ones), so recursive
// walkers — the evaluator, dump(), the destructors — stay well within the stack.
inline constexpr std::uint32_t kMaxExprHeight = 256;

struct Expr {
  using Node = std::variant<NumberLit, BoolLit, StringLit, VectorLit, ListLit, ListComprehension, NameRef,
                            UnaryExpr, BinaryExpr, CallExpr, MemberExpr, IndexExpr>;
  Expr() = default;
  Expr(SourceSpan where, Node what) : span(where), node(std::move(what)) {}

  SourceSpan span;
  std::uint32_t height = 1;  // nodes on the longest path down from here, this one included; beside the
                             // 12-byte span it fills what would be padding (a script holds millions)
  Node node;
};

// ---- statements --------------------------------------------------------------------------------

struct Stmt;
struct Block {
  std::vector<Stmt> statements;
  SourceSpan span;  // from '{' to '}'
};

enum class Orientation { Unspecified, Landscape, Portrait };

// solid NAME [(crease: 30, planarity: 0.003, ...)] { ITEMS }
struct SolidStmt {
  Name name;
  std::vector<Argument> options;  // as written, labels and spans kept; the runtime checks them
  SolidBody body;
};
struct LetStmt {
  Name name;
  ExprPtr value;
};
struct Param {
  Name name;
  ExprPtr default_value;  // null when the parameter has no default
};
// def NAME(params) = EXPR       (expression form: `body` is empty, `value` set)
// def NAME(params) { ... }      (block form: `value` null; `return EXPR` inside gives the result)
struct DefStmt {
  Name name;
  std::vector<Param> params;
  ExprPtr value;
  std::optional<Block> body;
};
struct ReturnStmt {
  ExprPtr value;  // null for a bare `return`
};
struct ForStmt {
  Name variable;
  ExprPtr iterable;
  Block body;
};
struct IfStmt {
  ExprPtr condition;
  Block then_block;
  std::optional<Block> else_block;  // `else if` is an else block holding one IfStmt
};
// `pen N` after a draw or `style hidden dashed|levels N`.
struct PenClause {
  ExprPtr number;
  SourceSpan span;  // from `pen` to the end of N
};
struct DrawStmt {  // draw EXPR [at EXPR] [pen N]
  ExprPtr object;
  ExprPtr transform;  // after `at`; null when absent
  std::optional<PenClause> pen;
};
struct CameraStmt {
  Name name;
  ExprPtr value;
};
struct AnimateStmt {  // animate frames N [fps F]
  ExprPtr frames;
  ExprPtr fps;  // null when absent
};
struct PaperSpec {
  std::optional<Name> size;  // "A4", "letter", "custom", ... as written
  Orientation orientation = Orientation::Unspecified;
  std::vector<Argument> options;  // (margin: 10, scale: 0.5, width: .., height: ..) as written
};
// output "pattern-{frame:03}.pdf" [paper SIZE [landscape|portrait] [(OPTIONS)] | landscape|portrait]
//        [plotter NAME]
struct OutputStmt {
  ExprPtr pattern;  // a StringLit expression
  PaperSpec paper;
  std::optional<Name> plotter;  // a name, or a plain string's text (its span includes the quotes)
};
struct PaperStmt {  // paper SIZE [landscape|portrait] [(OPTIONS)]
  PaperSpec paper;
};
struct StyleStmt {  // style hidden dashed|off|levels N [pen P]
  Name property;    // "hidden"
  Name value;       // "dashed", "off" or "levels"
  ExprPtr levels;   // N after `levels`; null otherwise
  std::optional<PenClause> pen;
};
struct IncludeStmt {  // include "file.hls"
  std::string path;
  SourceSpan path_span;
};
struct PenStmt {  // pen N (colour: "red", width: 0.35)
  ExprPtr number;
  std::vector<Argument> options;  // as written; the runtime checks them
};
struct LabelStmt {  // label TEXT at [page] POINT [size: MM] [pen N]
  ExprPtr text;
  ExprPtr point;
  bool on_page = false;  // `at page (x, y)`: page millimetres, not a world point
  ExprPtr size;          // null when absent
  std::optional<PenClause> pen;
};
struct ViewStmt {  // view NAME = CAMERA at page (X, Y) [KEY: EXPR ...]
  Name name;
  ExprPtr camera;
  ExprPtr point;
  std::vector<Argument> options;  // as written; the runtime checks them
};
struct ViewsStmt {  // views of PART [KEY: EXPR ...]
  ExprPtr object;
  std::vector<Argument> options;  // as written; the runtime checks them
};
struct DimensionStmt {  // dimension [angle at V] from P to Q [in VIEW] [KEY: EXPR ...]
  ExprPtr vertex;       // an angle's vertex; null for a distance
  ExprPtr from;
  ExprPtr to;
  std::optional<Name> view;       // absent: the sheet's only view
  std::vector<Argument> options;  // as written; the runtime checks them
};
struct PlotterStmt {  // plotter NAME { KEY: EXPR ... }
  Name name;
  std::vector<Argument> entries;  // each labelled with its key, as written
};

struct Stmt {
  SourceSpan span;
  std::variant<SolidStmt, LetStmt, DefStmt, ReturnStmt, ForStmt, IfStmt, DrawStmt, CameraStmt, AnimateStmt,
               OutputStmt, PaperStmt, StyleStmt, IncludeStmt, PenStmt, PlotterStmt, LabelStmt, ViewStmt,
               ViewsStmt, DimensionStmt>
      node;
};

struct Script {
  FileId file = 0;
  std::vector<Stmt> statements;
};

// ---- names and dumps (for tests, the REPL and error messages) ----------------------------------

const char* to_string(UnaryOp op);                // "-", "not"
const char* to_string(BinaryOp op);               // "then", "+", "..", ...
const char* statement_keyword(const Stmt& stmt);  // "solid", "let", ..., "pen", "plotter"

// A compact S-expression of a node, e.g. (draw (call post (+ 1 i)) (call translate (* 2 i) 0 0)).
std::string dump(const Expr& expr);
std::string dump(const Stmt& stmt);
std::string dump(const Script& script);  // one statement per line

}  // namespace hlr::lang
