// Internal to lang/: what the parser carries while it matches one statement. Not a public header.
//
// `items` is a stack of finished nodes. The control (parse_control.hpp) marks its height when a rule
// starts; when the rule succeeds its action finds its children above that mark and replaces them by
// one node; when it fails the stack is cut back to the mark, so backtracking never leaves stray
// nodes behind.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <variant>
#include <vector>

#include "lang/ast.hpp"

namespace hlr::lang::detail {

// An operator or word whose text matters to the parent: '+', 'then', 'landscape', a format spec.
struct Token {
  std::string_view text;
  SourceSpan span;
};

// call, member and index suffixes, folded onto their object by postfix_expr.
struct CallSuffix {
  std::vector<Argument> args;
  SourceSpan span;
};
struct MemberSuffix {
  Name member;
  SourceSpan span;
};
struct IndexSuffix {
  ExprPtr index;
  SourceSpan span;
};
// The name after `output ... plotter`, apart from the paper size's Name.
struct PlotterName {
  Name name;
};
// `label ... at page (x, y)`: the point is on the page.
struct PageMarker {};
// A vertex position of three plain numbers (grammar.hpp, literal_position).
struct LiteralPosition {
  std::array<double, 3> xyz;
};
// A vertex id in the solid block being read, interned there (SolidBody::intern).
struct VertexRef {
  std::uint32_t id;
};
// `hole ID ID ...` after a face's ids.
struct HoleRefs {
  std::vector<std::uint32_t> ids;
};

using Item =
    std::variant<Expr, Stmt, Token, Name, VertexRef, Argument, Param, StringPart, CallSuffix, MemberSuffix,
                 IndexSuffix, HoleRefs, Block, PenClause, PlotterName, PageMarker, LiteralPosition>;

// Thrown by the control (a failed must<>) and by actions; the parser turns it into a Diagnostic.
struct SyntaxError {
  const char* at = nullptr;  // where the failing rule began
  const char* message = "";
  const char* hint = nullptr;
  const char* opened_at = nullptr;  // for a missing closing bracket: where the bracket opened
  char opener = 0;
  bool expects_name = false;        // a reserved word here gets its own message
  bool statement_expected = false;  // nothing here starts a statement
};

// Brackets, blocks and prefix operators nested deeper than this are an error, not a stack overflow.
inline constexpr std::size_t kMaxNesting = 64;

struct ParseState {
  const SourceFile* file = nullptr;
  const char* base = nullptr;  // file->text().data(); offsets are pointer differences from it

  // Heights of `items` where the rules with actions now open began, innermost last. Pushed for
  // millions of rule attempts, so kept inline: std::vector's out-of-line push_back, reading back a
  // two-word argument just stored, was 6 % of parsing general code.
  class MarkStack {
   public:
    [[gnu::always_inline]] void push(std::size_t height) {
      if (size_ == heights_.size()) heights_.resize(heights_.size() * 2 + 64);
      heights_[size_++] = height;
    }
    [[gnu::always_inline]] void pop() { --size_; }
    std::size_t back() const { return heights_[size_ - 1]; }
    void clear() { size_ = 0; }

   private:
    std::vector<std::size_t> heights_;
    std::size_t size_ = 0;
  };
  std::vector<Item> items;
  MarkStack marks;
  std::vector<const char*> openers;  // unclosed brackets, innermost last
  std::size_t prefix_depth = 0;      // prefix operators and `else if` currently open
  const char* last_failed_at = nullptr;
  // The solid block being read: its items go straight here, not onto the stack. Blocks do not nest
  // (items hold no statements), and a block once begun is finished or the statement fails.
  SolidBody solid;
  bool plain_solid_items = true;  // ParseOptions::plain_solid_items
  bool plain_expressions = true;  // ParseOptions::plain_expressions

  std::size_t offset(const char* p) const { return static_cast<std::size_t>(p - base); }
  // The same at a span's width.
  std::uint32_t offset32(const char* p) const { return static_cast<std::uint32_t>(p - base); }
  SourceSpan span(const char* begin, const char* end) const { return file->span(offset(begin), offset(end)); }
};

}  // namespace hlr::lang::detail
