// Every function here mirrors a rule of grammar.hpp (named in its comment) and the action that builds
// its node (ast_builder.cpp, build_helpers.hpp): the same spans, the same heights. Where the grammar
// would raise an error, or meets a form read here by no function, the reader declines (returns false
// all the way up) and the grammar reads the whole expression again.
#include "lang/plain_expression.hpp"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "lang/build_helpers.hpp"
#include "lang/grammar.hpp"
#include "lang/plain_scan.hpp"

namespace hlr::lang {

namespace {

using detail::build::binary_op;
using detail::build::box;
using detail::build::join;
using detail::build::tallest_child;
using scan::is_digit;
using scan::is_first;
using scan::word_at;

class Reader {
 public:
  Reader(const char* base, const char* end, FileId file, std::size_t nesting)
      : base_(base), end_(end), file_(file), nesting_(nesting) {}

  // expression (then_expr). Each reader takes `p` at its construct and leaves it just past its text:
  // trailing padding is not part of a rule's match.
  bool expression(const char*& p, Expr& out) {
    return left_assoc(p, out, &Reader::or_level, &Reader::then_at);
  }

 private:
  using Level = bool (Reader::*)(const char*&, Expr&);
  using OperatorAt = std::size_t (Reader::*)(const char*) const;

  SourceSpan span(const char* begin, const char* end) const {
    return {file_, static_cast<std::uint32_t>(begin - base_), static_cast<std::uint32_t>(end - base_)};
  }
  bool at(const char* p, char c) const { return p < end_ && *p == c; }
  const char* pad(const char* p) const { return scan::skip_padding(p, end_); }
  bool word_is(const char* p, std::string_view word) const { return word_at(p, end_) == word; }

  // with_height, declining where it would raise its error.
  bool finish(Expr& e) const {
    e.height = tallest_child(e) + 1;
    return e.height <= kMaxExprHeight;
  }
  // Brackets and prefix operators open around what is being read, the grammar's count (parse_control):
  // declined well before its limit, so the grammar raises its error itself.
  bool enter() { return nesting_ + ++depth_ < detail::kMaxNesting - 4; }
  void leave() { --depth_; }

  // ---- binary levels: `next (op next)*` left-nested (fold_binary), or one op at most -----------------

  bool left_assoc(const char*& p, Expr& out, Level next, OperatorAt op_at) {
    if (!(this->*next)(p, out)) return false;
    for (;;) {
      const char* op = pad(p);
      const std::size_t length = (this->*op_at)(op);
      if (length == 0) return true;
      const char* q = pad(op + length);
      Expr rhs;
      if (!(this->*next)(q, rhs)) return false;  // must< X_rhs >
      binary(out, op, length, std::move(rhs));
      if (!finish(out)) return false;
      p = q;
    }
  }

  // cmp_expr, range_expr: `next (op next)?` and then no second op (cmp_single, range_single).
  bool non_assoc(const char*& p, Expr& out, Level next, OperatorAt op_at) {
    if (!(this->*next)(p, out)) return false;
    const char* op = pad(p);
    const std::size_t length = (this->*op_at)(op);
    if (length == 0) return true;
    const char* q = pad(op + length);
    Expr rhs;
    if (!(this->*next)(q, rhs)) return false;
    if ((this->*op_at)(pad(q)) != 0) return false;  // `a < b < c`: the grammar's error
    binary(out, op, length, std::move(rhs));
    if (!finish(out)) return false;
    p = q;
    return true;
  }

  void binary(Expr& acc, const char* op, std::size_t length, Expr&& rhs) {
    const SourceSpan whole = join(acc.span, rhs.span);
    BinaryExpr node{box(std::move(acc)), box(std::move(rhs)), span(op, op + length),
                    binary_op(std::string_view(op, length))};
    acc = Expr(whole, std::move(node));
  }

  std::size_t keyword_at(const char* p, std::string_view word) const {
    return word_is(p, word) ? word.size() : 0;
  }
  std::size_t then_at(const char* p) const { return keyword_at(p, "then"); }  // then_op
  std::size_t or_at(const char* p) const { return keyword_at(p, "or"); }      // or_op
  std::size_t and_at(const char* p) const { return keyword_at(p, "and"); }    // and_op
  std::size_t cmp_at(const char* p) const {                                   // cmp_op
    if (p + 1 < end_ && p[1] == '=' && (*p == '=' || *p == '!' || *p == '<' || *p == '>')) return 2;
    return at(p, '<') || at(p, '>') ? 1 : 0;
  }
  std::size_t range_at(const char* p) const { return at(p, '.') && at(p + 1, '.') ? 2 : 0; }  // range_op
  std::size_t add_at(const char* p) const { return at(p, '+') || at(p, '-') ? 1 : 0; }        // add_op
  std::size_t mul_at(const char* p) const {                                                   // mul_op
    return at(p, '*') || at(p, '/') || at(p, '%') ? 1 : 0;
  }

  bool or_level(const char*& p, Expr& out) { return left_assoc(p, out, &Reader::and_level, &Reader::or_at); }
  bool and_level(const char*& p, Expr& out) {
    return left_assoc(p, out, &Reader::not_level, &Reader::and_at);
  }
  bool cmp_level(const char*& p, Expr& out) {
    return non_assoc(p, out, &Reader::range_level, &Reader::cmp_at);
  }
  bool range_level(const char*& p, Expr& out) {
    return non_assoc(p, out, &Reader::add_level, &Reader::range_at);
  }
  bool add_level(const char*& p, Expr& out) {
    return left_assoc(p, out, &Reader::mul_level, &Reader::add_at);
  }
  bool mul_level(const char*& p, Expr& out) {
    return left_assoc(p, out, &Reader::neg_level, &Reader::mul_at);
  }

  // ---- prefix levels (not_expr, neg_expr; make_prefix): the span runs from the operator ------------

  bool not_level(const char*& p, Expr& out) {
    if (!word_is(p, "not")) return cmp_level(p, out);
    return prefix(p, 3, UnaryOp::Not, &Reader::not_level, out);
  }
  bool neg_level(const char*& p, Expr& out) {
    if (!at(p, '-')) return postfix(p, out);
    return prefix(p, 1, UnaryOp::Negate, &Reader::neg_level, out);
  }
  bool prefix(const char*& p, std::size_t length, UnaryOp op, Level operand_level, Expr& out) {
    if (!enter()) return false;  // not_operand, neg_operand nest
    const char* q = pad(p + length);
    Expr operand;
    if (!(this->*operand_level)(q, operand)) return false;
    leave();
    out = Expr(span(p, q), UnaryExpr{op, box(std::move(operand))});
    if (!finish(out)) return false;
    p = q;
    return true;
  }

  // ---- postfix_expr: primary, then calls, members and indexes, each joined to what precedes it -----

  bool postfix(const char*& p, Expr& out) {
    if (!primary(p, out)) return false;
    for (;;) {
      const char* q = pad(p);
      if (at(q, '(')) {
        if (!call(q, out)) return false;
      } else if (at(q, '[')) {
        if (!index(q, out)) return false;
      } else if (at(q, '.') && !at(q + 1, '.')) {
        if (!member(q, out)) return false;
      } else {
        return true;
      }
      if (!finish(out)) return false;
      p = q;
    }
  }

  // call_suffix: `(` [argument (`,` argument)*] `)`.
  bool call(const char*& p, Expr& callee) {
    if (!enter()) return false;
    const char* q = pad(p + 1);
    std::vector<Argument> args;
    if (!at(q, ')')) {
      for (;;) {
        Argument arg;
        if (!argument(q, arg)) return false;
        args.push_back(std::move(arg));
        const char* comma = pad(q);
        if (!at(comma, ',')) break;
        q = pad(comma + 1);
      }
      q = pad(q);
      if (!at(q, ')')) return false;
    }
    leave();
    const SourceSpan whole = join(callee.span, span(p, q + 1));
    callee = Expr(whole, CallExpr{box(std::move(callee)), std::move(args)});
    p = q + 1;
    return true;
  }

  // argument: `NAME : expression` (arg_label, labeled_value) or an expression.
  bool argument(const char*& p, Argument& arg) {
    const std::string_view word = word_at(p, end_);
    if (!word.empty() && !grammar::reserved::contains(word)) {
      const char* colon = pad(p + word.size());
      if (at(colon, ':')) {
        const char* q = pad(colon + 1);
        Expr value;
        if (!expression(q, value)) return false;
        arg.label = std::make_unique<Name>(Name{std::string(word), span(p, p + word.size())});
        arg.value = box(std::move(value));
        arg.span = span(p, q);
        p = q;
        return true;
      }
    }
    const char* q = p;
    Expr value;
    if (!expression(q, value)) return false;
    arg.value = box(std::move(value));
    arg.span = span(p, q);
    p = q;
    return true;
  }

  // index_suffix: `[` expression `]`.
  bool index(const char*& p, Expr& object) {
    if (!enter()) return false;
    const char* q = pad(p + 1);
    Expr value;
    if (!expression(q, value)) return false;
    q = pad(q);
    if (!at(q, ']')) return false;
    leave();
    const SourceSpan whole = join(object.span, span(p, q + 1));
    object = Expr(whole, IndexExpr{box(std::move(object)), box(std::move(value))});
    p = q + 1;
    return true;
  }

  // member_suffix: `.` (not `..`) then a name.
  bool member(const char*& p, Expr& object) {
    const char* q = pad(p + 1);
    const std::string_view word = word_at(q, end_);
    if (word.empty() || grammar::reserved::contains(word)) return false;
    const SourceSpan whole = join(object.span, span(p, q + word.size()));
    object =
        Expr(whole, MemberExpr{box(std::move(object)),
                               std::make_unique<Name>(Name{std::string(word), span(q, q + word.size())})});
    p = q + word.size();
    return true;
  }

  // ---- primary: number, string_lit, bool_lit, paren_expr, list_lit, name_ref --------------------------

  bool primary(const char*& p, Expr& out) {
    if (p >= end_) return false;
    if (is_digit(*p)) return number(p, out);
    if (*p == '"') return string(p, out);
    if (*p == '(') return paren(p, out);
    if (*p == '[') return list(p, out);
    if (!is_first(*p)) return false;
    const std::string_view word = word_at(p, end_);
    if (word == "true" || word == "false") {
      out = Expr(span(p, p + word.size()), BoolLit{word == "true"});
    } else if (grammar::reserved::contains(word)) {
      return false;
    } else {
      out = Expr(span(p, p + word.size()), NameRef{std::string(word)});
    }
    p += word.size();
    return true;
  }

  bool number(const char*& p, Expr& out) {
    const char* q = p;
    NumberLit lit;
    if (!scan::read_number(q, end_, lit.value, /*signed_number=*/false)) return false;
    lit.integer =
        std::string_view(p, static_cast<std::size_t>(q - p)).find_first_of(".eE") == std::string_view::npos;
    out = Expr(span(p, q), lit);
    p = q;
    return true;
  }

  // string_lit without interpolation: text and escapes make one part (make_string merges them).
  bool string(const char*& p, Expr& out) {
    const char* q = p + 1;
    std::string text;
    const char* parts_begin = nullptr;
    for (;;) {
      if (q >= end_) return false;
      const char c = *q;
      if (c == '"') break;
      if (c == '{' || c == '\n' || c == '\r') return false;  // interpolation: the grammar's
      if (!parts_begin) parts_begin = q;
      if (c == '\\') {  // escape
        if (q + 1 >= end_) return false;
        const char e = q[1];
        if (e != '"' && e != '\\' && e != 'n' && e != 't' && e != '{' && e != '}') return false;
        text += e == 'n' ? '\n' : e == 't' ? '\t' : e;
        q += 2;
      } else {  // string_text
        const char* run = q;
        while (q < end_ && *q != '"' && *q != '\\' && *q != '{' && *q != '\n' && *q != '\r') ++q;
        text.append(run, q);
      }
    }
    StringLit lit;
    if (parts_begin) lit.parts.push_back(StringPart{std::move(text), nullptr, {}, span(parts_begin, q)});
    out = Expr(span(p, q + 1), std::move(lit));
    p = q + 1;
    return true;
  }

  // paren_expr: `(e)` is e itself; `(x, y)` and `(x, y, z)` are vectors, (x, y) with a 0 spanning it all.
  bool paren(const char*& p, Expr& out) {
    if (!enter()) return false;
    const char* q = pad(p + 1);
    Expr first;
    if (!expression(q, first)) return false;
    q = pad(q);
    if (at(q, ')')) {
      leave();
      out = std::move(first);
      p = q + 1;
      return true;
    }
    if (!at(q, ',')) return false;
    VectorLit vec;
    vec.components[0] = box(std::move(first));
    for (std::size_t i = 1; i < 3; ++i) {
      q = pad(q + 1);
      Expr component;
      if (!expression(q, component)) return false;
      vec.components[i] = box(std::move(component));
      q = pad(q);
      if (at(q, ')')) break;
      if (i == 2 || !at(q, ',')) return false;
    }
    leave();
    const SourceSpan whole = span(p, q + 1);
    if (!vec.components[2]) vec.components[2] = box(Expr(whole, NumberLit{0, true}));
    out = Expr(whole, std::move(vec));
    p = q + 1;
    return finish(out);
  }

  // list_lit: `[]`, `[a, b, ...]` or `[element for NAME in iterable (if condition)]` (comp_for).
  bool list(const char*& p, Expr& out) {
    if (!enter()) return false;
    const char* q = pad(p + 1);
    if (at(q, ']')) {
      leave();
      out = Expr(span(p, q + 1), ListLit{});
      p = q + 1;
      return true;
    }
    Expr first;
    if (!expression(q, first)) return false;
    q = pad(q);
    if (word_is(q, "for")) return comprehension(p, q, std::move(first), out);
    ListLit items;
    items.items.push_back(box(std::move(first)));
    while (at(q, ',')) {
      q = pad(q + 1);
      Expr item;
      if (!expression(q, item)) return false;
      items.items.push_back(box(std::move(item)));
      q = pad(q);
    }
    if (!at(q, ']')) return false;
    leave();
    out = Expr(span(p, q + 1), std::move(items));
    p = q + 1;
    return finish(out);
  }

  // comp_for, from `for` at `q`; the list opened at `p`.
  bool comprehension(const char*& p, const char* q, Expr&& element, Expr& out) {
    q = pad(q + 3);
    const std::string_view variable = word_at(q, end_);
    if (variable.empty() || grammar::reserved::contains(variable)) return false;
    auto name = std::make_unique<Name>(Name{std::string(variable), span(q, q + variable.size())});
    q = pad(q + variable.size());
    if (!word_is(q, "in")) return false;
    q = pad(q + 2);
    Expr iterable;
    if (!expression(q, iterable)) return false;
    q = pad(q);
    ExprPtr condition;
    if (word_is(q, "if")) {
      q = pad(q + 2);
      Expr filter;
      if (!expression(q, filter)) return false;
      condition = box(std::move(filter));
      q = pad(q);
    }
    if (!at(q, ']')) return false;
    leave();
    out = Expr(span(p, q + 1), ListComprehension{box(std::move(element)), std::move(name),
                                                 box(std::move(iterable)), std::move(condition)});
    p = q + 1;
    return finish(out);
  }

  const char* base_;
  const char* end_;
  FileId file_;
  std::size_t nesting_;
  std::size_t depth_ = 0;
};

}  // namespace

std::size_t read_plain_expression(const char* base, const char* at, const char* end, FileId file,
                                  std::size_t nesting, Expr& out) {
  Reader reader(base, end, file, nesting);
  const char* p = at;
  if (!reader.expression(p, out)) return 0;
  return static_cast<std::size_t>(p - at);
}

}  // namespace hlr::lang
