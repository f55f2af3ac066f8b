// Internal to lang/: the pieces the AST actions (ast_builder.cpp) are made of — access to a rule's
// children on the node stack, and the action kinds several rules share (push a name or token, fold
// a precedence level, build a prefix operation, a string, an argument, a block, a parameter).
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <type_traits>

#include "lang/ast.hpp"
#include "lang/parse_state.hpp"

namespace hlr::lang::detail::build {

// ---- helpers on the node stack ------------------------------------------------------------------

inline std::size_t first_child(const ParseState& s) { return s.marks.back(); }
inline std::size_t child_count(const ParseState& s) { return s.items.size() - first_child(s); }

template <typename T>
T take(Item& item) {
  return std::get<T>(std::move(item));
}
template <typename T>
bool holds(const Item& item) {
  return std::holds_alternative<T>(item);
}

// Removes the rule's children and pushes its node.
inline void replace_children(ParseState& s, Item node) {
  s.items.erase(s.items.begin() + static_cast<std::ptrdiff_t>(first_child(s)), s.items.end());
  s.items.push_back(std::move(node));
}

template <typename Input>
SourceSpan span_of(const Input& in, const ParseState& s) {
  return s.span(in.begin(), in.end());
}

inline ExprPtr box(Expr&& expr) { return std::make_unique<Expr>(std::move(expr)); }

inline std::uint32_t height_of(const ExprPtr& e) { return e ? e->height : 0; }

// The height of a node's tallest child: 0 for a leaf.
inline std::uint32_t tallest_child(const Expr& e) {
  std::uint32_t below = 0;
  auto see = [&](const ExprPtr& child) { below = std::max(below, height_of(child)); };
  std::visit(
      [&](const auto& node) {
        using T = std::decay_t<decltype(node)>;
        if constexpr (std::is_same_v<T, StringLit>) {
          for (const auto& part : node.parts) see(part.expr);
        } else if constexpr (std::is_same_v<T, VectorLit>) {
          for (const auto& c : node.components) see(c);
        } else if constexpr (std::is_same_v<T, ListLit>) {
          for (const auto& item : node.items) see(item);
        } else if constexpr (std::is_same_v<T, ListComprehension>) {
          see(node.element);
          see(node.iterable);
          see(node.condition);
        } else if constexpr (std::is_same_v<T, UnaryExpr>) {
          see(node.operand);
        } else if constexpr (std::is_same_v<T, BinaryExpr>) {
          see(node.lhs);
          see(node.rhs);
        } else if constexpr (std::is_same_v<T, CallExpr>) {
          see(node.callee);
          for (const auto& arg : node.args) see(arg.value);
        } else if constexpr (std::is_same_v<T, MemberExpr>) {
          see(node.object);
        } else if constexpr (std::is_same_v<T, IndexExpr>) {
          see(node.object);
          see(node.index);
        }
      },
      e.node);
  return below;
}

// Sets a new composite node's height from its children's and enforces kMaxExprHeight.
inline Expr with_height(Expr&& e, const ParseState& s) {
  const std::uint32_t below = tallest_child(e);
  e.height = below + 1;
  if (e.height > kMaxExprHeight) {
    throw SyntaxError{s.base + e.span.begin, "expression too deep: more than 256 nested operations",
                      "split it with 'let', or build long sums with a loop"};
  }
  return std::move(e);
}

inline SourceSpan join(const SourceSpan& a, const SourceSpan& b) { return {a.file, a.begin, b.end}; }

inline BinaryOp binary_op(std::string_view text) {
  if (text == "then") return BinaryOp::Then;
  if (text == "or") return BinaryOp::Or;
  if (text == "and") return BinaryOp::And;
  if (text == "==") return BinaryOp::Eq;
  if (text == "!=") return BinaryOp::Ne;
  if (text == "<") return BinaryOp::Lt;
  if (text == "<=") return BinaryOp::Le;
  if (text == ">") return BinaryOp::Gt;
  if (text == ">=") return BinaryOp::Ge;
  if (text == "..") return BinaryOp::Range;
  if (text == "+") return BinaryOp::Add;
  if (text == "-") return BinaryOp::Sub;
  if (text == "*") return BinaryOp::Mul;
  if (text == "/") return BinaryOp::Div;
  return BinaryOp::Mod;
}

// ---- action kinds shared by several rules -------------------------------------------------------

struct push_name {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    s.items.emplace_back(Name{std::string(in.string_view()), span_of(in, s)});
  }
};

struct push_token {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    s.items.emplace_back(Token{in.string_view(), span_of(in, s)});
  }
};

// level := operand (op operand)*  ->  left-nested BinaryExpr
struct fold_binary {
  template <typename Input>
  static void apply(const Input& /*in*/, ParseState& s) {
    const std::size_t first = first_child(s);
    if (child_count(s) == 1) return;
    Expr acc = take<Expr>(s.items[first]);
    for (std::size_t i = first + 1; i + 1 < s.items.size(); i += 2) {
      Token op = take<Token>(s.items[i]);
      Expr rhs = take<Expr>(s.items[i + 1]);
      const SourceSpan span = join(acc.span, rhs.span);
      acc = with_height(
          Expr{span, BinaryExpr{box(std::move(acc)), box(std::move(rhs)), op.span, binary_op(op.text)}}, s);
    }
    replace_children(s, std::move(acc));
  }
};

// level := op operand | next-level  ->  UnaryExpr when the operator is there
struct make_prefix {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    if (child_count(s) == 1) return;
    const std::size_t first = first_child(s);
    const Token op = take<Token>(s.items[first]);
    Expr operand = take<Expr>(s.items[first + 1]);
    const UnaryOp kind = op.text == "-" ? UnaryOp::Negate : UnaryOp::Not;
    replace_children(s, with_height(Expr{span_of(in, s), UnaryExpr{kind, box(std::move(operand))}}, s));
  }
};

struct make_string {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    StringLit lit;
    for (std::size_t i = first_child(s); i < s.items.size(); ++i) {
      StringPart part = take<StringPart>(s.items[i]);
      if (!part.expr && !lit.parts.empty() && !lit.parts.back().expr) {
        lit.parts.back().text += part.text;
        lit.parts.back().span.end = part.span.end;
      } else {
        lit.parts.push_back(std::move(part));
      }
    }
    replace_children(s, with_height(Expr{span_of(in, s), std::move(lit)}, s));
  }
};

struct make_argument {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    const std::size_t first = first_child(s);
    Argument arg;
    arg.span = span_of(in, s);
    if (holds<Name>(s.items[first])) arg.label = std::make_unique<Name>(take<Name>(s.items[first]));
    arg.value = box(take<Expr>(s.items.back()));
    replace_children(s, std::move(arg));
  }
};

struct make_block {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    Block block;
    block.span = span_of(in, s);
    for (std::size_t i = first_child(s); i < s.items.size(); ++i)
      block.statements.push_back(take<Stmt>(s.items[i]));
    replace_children(s, std::move(block));
  }
};

struct make_param {
  template <typename Input>
  static void apply(const Input& /*in*/, ParseState& s) {
    const std::size_t first = first_child(s);
    Param param{take<Name>(s.items[first]), nullptr};
    if (child_count(s) == 2) param.default_value = box(take<Expr>(s.items[first + 1]));
    replace_children(s, std::move(param));
  }
};

// Replaces the children by a statement built from them by `build(children, span)`.
template <typename Build>
void make_statement(const SourceSpan& span, ParseState& s, Build build) {
  const std::size_t first = first_child(s);
  auto node = build(s.items.begin() + static_cast<std::ptrdiff_t>(first), s.items.end());
  replace_children(s, Stmt{span, std::move(node)});
}

inline ExprPtr optional_expr(std::vector<Item>::iterator it, std::vector<Item>::iterator end) {
  return it != end && holds<Expr>(*it) ? box(take<Expr>(*it)) : nullptr;
}

// [SIZE] [landscape|portrait] [OPTIONS...]: a Name, a Token, Arguments.
inline PaperSpec paper_spec(std::vector<Item>::iterator it, std::vector<Item>::iterator end) {
  PaperSpec paper;
  for (; it != end; ++it) {
    if (holds<Name>(*it)) paper.size = take<Name>(*it);
    if (holds<Token>(*it)) {
      paper.orientation =
          std::get<Token>(*it).text == "landscape" ? Orientation::Landscape : Orientation::Portrait;
    }
    if (holds<Argument>(*it)) paper.options.push_back(take<Argument>(*it));
  }
  return paper;
}

}  // namespace hlr::lang::detail::build
