// PEGTL actions that build the AST, and nothing else: no evaluation, no name lookup. Each action
// takes the nodes its rule's children left on the stack (above the rule's mark, see parse_state.hpp)
// and replaces them by one node spanning the rule's text.
#include "lang/ast_builder.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <string>
#include <tao/pegtl.hpp>

#include "lang/build_helpers.hpp"
#include "lang/grammar.hpp"
#include "lang/parse_control.hpp"

namespace hlr::lang::detail {
namespace {

namespace g = grammar;

using namespace build;  // NOLINT: the helpers are this file's vocabulary

template <typename Rule>
struct action : tao::pegtl::nothing<Rule> {};

// ---- literals -----------------------------------------------------------------------------------

template <>
struct action<g::number> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    const std::string_view text = in.string_view();
    NumberLit lit;
    lit.integer = text.find_first_of(".eE") == std::string_view::npos;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), lit.value);
    if (result.ec != std::errc()) {
      throw SyntaxError{in.begin(), "number out of range: numbers must lie within about 1e308",
                        "write a smaller number, or scale the scene"};
    }
    s.items.emplace_back(Expr{span_of(in, s), lit});
  }
};

template <>
struct action<g::bool_lit> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    s.items.emplace_back(Expr{span_of(in, s), BoolLit{in.string_view() == "true"}});
  }
};

template <>
struct action<g::string_text> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    s.items.emplace_back(StringPart{std::string(in.string_view()), nullptr, {}, span_of(in, s)});
  }
};

template <>
struct action<g::escape> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    const char c = in.string_view()[1];
    const char resolved = c == 'n' ? '\n' : c == 't' ? '\t' : c;
    s.items.emplace_back(StringPart{std::string(1, resolved), nullptr, {}, span_of(in, s)});
  }
};

template <>
struct action<g::interp_format> : push_token {};

template <>
struct action<g::interpolation> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    const std::size_t first = first_child(s);
    StringPart part{{}, box(take<Expr>(s.items[first])), {}, span_of(in, s)};
    if (child_count(s) == 2) part.format = std::string(std::get<Token>(s.items[first + 1]).text);
    replace_children(s, std::move(part));
  }
};

template <>
struct action<g::string_lit> : make_string {};

// ---- expressions --------------------------------------------------------------------------------

template <>
struct action<g::paren_expr> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    if (child_count(s) == 1) return;  // (e): the inner expression, as it is
    const std::size_t first = first_child(s);
    VectorLit vec;
    const std::size_t given = child_count(s);  // (x, y) or (x, y, z)
    for (std::size_t i = 0; i < given; ++i) vec.components[i] = box(take<Expr>(s.items[first + i]));
    if (given == 2) {
      // (x, y) is the point (x, y, 0): the third component is a 0 spanning the whole literal.
      vec.components[2] = box(Expr{span_of(in, s), NumberLit{0, true}});
    }
    replace_children(s, with_height(Expr{span_of(in, s), std::move(vec)}, s));
  }
};

template <>
struct action<g::comp_variable> : push_name {};

// [element for variable in iterable (if condition)] when a Name follows the first item, else a list.
template <>
struct action<g::list_lit> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    const std::size_t first = first_child(s);
    if (child_count(s) >= 3 && holds<Name>(s.items[first + 1])) {
      ListComprehension comp{box(take<Expr>(s.items[first])),
                             std::make_unique<Name>(take<Name>(s.items[first + 1])),
                             box(take<Expr>(s.items[first + 2])), nullptr};
      if (child_count(s) == 4) comp.condition = box(take<Expr>(s.items[first + 3]));
      replace_children(s, with_height(Expr{span_of(in, s), std::move(comp)}, s));
      return;
    }
    ListLit list;
    for (std::size_t i = first_child(s); i < s.items.size(); ++i)
      list.items.push_back(box(take<Expr>(s.items[i])));
    replace_children(s, with_height(Expr{span_of(in, s), std::move(list)}, s));
  }
};

template <>
struct action<g::name_ref> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    s.items.emplace_back(Expr{span_of(in, s), NameRef{std::string(in.string_view())}});
  }
};

template <>
struct action<g::arg_label> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    const std::string_view text = in.string_view();
    std::size_t n = 0;
    while (n < text.size() && (std::isalnum(static_cast<unsigned char>(text[n])) || text[n] == '_')) ++n;
    s.items.emplace_back(Name{std::string(text.substr(0, n)), s.span(in.begin(), in.begin() + n)});
  }
};

template <>
struct action<g::argument> : make_argument {};

template <>
struct action<g::call_suffix> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    CallSuffix call{{}, span_of(in, s)};
    for (std::size_t i = first_child(s); i < s.items.size(); ++i)
      call.args.push_back(take<Argument>(s.items[i]));
    replace_children(s, std::move(call));
  }
};

template <>
struct action<g::member_name> : push_name {};

template <>
struct action<g::member_suffix> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    replace_children(s, MemberSuffix{take<Name>(s.items.back()), span_of(in, s)});
  }
};

template <>
struct action<g::index_suffix> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    replace_children(s, IndexSuffix{box(take<Expr>(s.items.back())), span_of(in, s)});
  }
};

template <>
struct action<g::postfix_expr> {
  template <typename Input>
  static void apply(const Input& /*in*/, ParseState& s) {
    if (child_count(s) == 1) return;
    const std::size_t first = first_child(s);
    Expr acc = take<Expr>(s.items[first]);
    for (std::size_t i = first + 1; i < s.items.size(); ++i) {
      Item& suffix = s.items[i];
      if (holds<CallSuffix>(suffix)) {
        auto call = take<CallSuffix>(suffix);
        const SourceSpan span = join(acc.span, call.span);
        acc = with_height(Expr{span, CallExpr{box(std::move(acc)), std::move(call.args)}}, s);
      } else if (holds<MemberSuffix>(suffix)) {
        auto member = take<MemberSuffix>(suffix);
        const SourceSpan span = join(acc.span, member.span);
        acc = with_height(
            Expr{span, MemberExpr{box(std::move(acc)), std::make_unique<Name>(std::move(member.member))}}, s);
      } else {
        auto index = take<IndexSuffix>(suffix);
        const SourceSpan span = join(acc.span, index.span);
        acc = with_height(Expr{span, IndexExpr{box(std::move(acc)), std::move(index.index)}}, s);
      }
    }
    replace_children(s, std::move(acc));
  }
};

// clang-format off
template <> struct action<g::neg_op> : push_token {};
template <> struct action<g::not_op> : push_token {};
template <> struct action<g::mul_op> : push_token {};
template <> struct action<g::add_op> : push_token {};
template <> struct action<g::range_op> : push_token {};
template <> struct action<g::cmp_op> : push_token {};
template <> struct action<g::and_op> : push_token {};
template <> struct action<g::or_op> : push_token {};
template <> struct action<g::then_op> : push_token {};
template <> struct action<g::neg_expr> : make_prefix {};
template <> struct action<g::not_expr> : make_prefix {};
template <> struct action<g::mul_expr> : fold_binary {};
template <> struct action<g::add_expr> : fold_binary {};
template <> struct action<g::range_expr> : fold_binary {};
template <> struct action<g::cmp_expr> : fold_binary {};
template <> struct action<g::and_expr> : fold_binary {};
template <> struct action<g::or_expr> : fold_binary {};
template <> struct action<g::then_expr> : fold_binary {};
// clang-format on

// ---- solids -------------------------------------------------------------------------------------

// Vertex ids are interned in the block being read (ParseState::solid): a number by its value, so that
// "01" and "1" are one vertex, a name as written.
template <>
struct action<g::id_number> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    const std::string_view text = in.string_view();
    std::int64_t number = 0;
    if (std::from_chars(text.data(), text.data() + text.size(), number).ec != std::errc()) {
      throw SyntaxError{in.begin(), "vertex id too large: numeric ids must be below 2^63",
                        "use a smaller number or a name"};
    }
    s.items.emplace_back(VertexRef{s.solid.intern(std::to_string(number))});
  }
};

template <>
struct action<g::id_name> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    s.items.emplace_back(VertexRef{s.solid.intern(in.string_view())});
  }
};

template <>
struct action<g::literal_position> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    // The rule matched "(" n "," n "," n ")" with blanks between: each number starts at the first
    // character that is neither a bracket, a comma nor a blank.
    const std::string_view text = in.string_view();
    const char* p = text.data();
    const char* const end = text.data() + text.size();
    LiteralPosition position{};
    for (double& v : position.xyz) {
      while (p < end && (*p == '(' || *p == ',' || *p == ' ' || *p == '\t')) ++p;
      const auto result = std::from_chars(p, end, v);
      if (result.ec != std::errc())
        throw SyntaxError{p, "number out of range: numbers must lie within about 1e308",
                          "write a smaller number, or scale the scene"};
      p = result.ptr;
    }
    s.items.emplace_back(position);
  }
};

template <>
struct action<g::vertex_decl> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    const std::size_t first = first_child(s);
    const std::uint32_t id = std::get<VertexRef>(s.items[first]).id;
    const auto begin = s.offset32(in.begin()), end = s.offset32(in.end());
    if (holds<LiteralPosition>(s.items[first + 1]))
      s.solid.add_vertex(id, std::get<LiteralPosition>(s.items[first + 1]).xyz, begin, end);
    else
      s.solid.add_vertex(id, box(take<Expr>(s.items[first + 1])), begin, end);
    s.items.resize(first);
  }
};

template <>
struct action<g::hole_clause> {
  template <typename Input>
  static void apply(const Input& /*in*/, ParseState& s) {
    HoleRefs hole;
    for (std::size_t i = first_child(s); i < s.items.size(); ++i)
      hole.ids.push_back(std::get<VertexRef>(s.items[i]).id);
    replace_children(s, std::move(hole));
  }
};

template <>
struct action<g::face_decl> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    std::vector<std::uint32_t> refs, ring_ends;
    for (std::size_t i = first_child(s); i < s.items.size(); ++i) {
      if (const auto* ref = std::get_if<VertexRef>(&s.items[i])) {
        refs.push_back(ref->id);
        continue;
      }
      if (ring_ends.empty()) ring_ends.push_back(static_cast<std::uint32_t>(refs.size()));
      const HoleRefs& hole = std::get<HoleRefs>(s.items[i]);
      refs.insert(refs.end(), hole.ids.begin(), hole.ids.end());
      ring_ends.push_back(static_cast<std::uint32_t>(refs.size()));
    }
    if (ring_ends.empty()) ring_ends.push_back(static_cast<std::uint32_t>(refs.size()));
    s.solid.add_face(refs, ring_ends, s.offset32(in.begin()), s.offset32(in.end()));
    s.items.resize(first_child(s));
  }
};

template <>
struct action<g::line_decl> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    const std::size_t first = first_child(s);
    s.solid.add_line(std::get<VertexRef>(s.items[first]).id, std::get<VertexRef>(s.items[first + 1]).id,
                     s.offset32(in.begin()), s.offset32(in.end()));
    s.items.resize(first);
  }
};

// A new block starts empty: a failed statement before may have left items.
template <>
struct action<g::solid_open> {
  template <typename Input>
  static void apply(const Input& /*in*/, ParseState& s) {
    s.solid.restart(s.file->id());
  }
};

template <>
struct action<g::solid_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [&](auto it, auto end) {
      SolidStmt solid{take<Name>(*it), {}, s.solid.take_compact()};
      for (++it; it != end && holds<Argument>(*it); ++it) solid.options.push_back(take<Argument>(*it));
      return solid;
    });
  }
};

// ---- statements ---------------------------------------------------------------------------------

// clang-format off
template <> struct action<g::solid_name> : push_name {};
template <> struct action<g::let_name> : push_name {};
template <> struct action<g::def_name> : push_name {};
template <> struct action<g::param_name> : push_name {};
template <> struct action<g::for_variable> : push_name {};
template <> struct action<g::camera_name> : push_name {};
template <> struct action<g::paper_size> : push_name {};
template <> struct action<g::plotter_name> : push_name {};
template <> struct action<g::view_name> : push_name {};
template <> struct action<g::dimension_view> : push_name {};
template <> struct action<g::style_property> : push_name {};
template <> struct action<g::style_word> : push_name {};
template <> struct action<g::style_levels_word> : push_name {};
template <> struct action<g::orientation> : push_token {};
template <> struct action<g::param> : make_param {};
template <> struct action<g::block> : make_block {};
// clang-format on

// `else if ...` becomes an else block holding that one if statement.
template <>
struct action<g::else_body> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    if (!holds<Stmt>(s.items.back())) return;
    Block block{{}, span_of(in, s)};
    block.statements.push_back(take<Stmt>(s.items.back()));
    replace_children(s, std::move(block));
  }
};

template <>
struct action<g::let_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [](auto it, auto) {
      return LetStmt{take<Name>(it[0]), box(take<Expr>(it[1]))};
    });
  }
};

template <>
struct action<g::def_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [](auto it, auto end) {
      DefStmt def{take<Name>(*it), {}, nullptr, std::nullopt};
      for (++it; holds<Param>(*it); ++it) def.params.push_back(take<Param>(*it));
      if (holds<Block>(*it)) {
        def.body = take<Block>(*it);
      } else {
        def.value = box(take<Expr>(*it));
      }
      (void)end;
      return def;
    });
  }
};

template <>
struct action<g::return_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [](auto it, auto end) { return ReturnStmt{optional_expr(it, end)}; });
  }
};

template <>
struct action<g::for_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [](auto it, auto) {
      return ForStmt{take<Name>(it[0]), box(take<Expr>(it[1])), take<Block>(it[2])};
    });
  }
};

template <>
struct action<g::if_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [](auto it, auto end) {
      IfStmt stmt{box(take<Expr>(it[0])), take<Block>(it[1]), std::nullopt};
      if (end - it == 3) stmt.else_block = take<Block>(it[2]);
      return stmt;
    });
  }
};

// pen N -> a PenClause spanning `pen N`
template <>
struct action<g::pen_clause> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    replace_children(s, PenClause{box(take<Expr>(s.items.back())), span_of(in, s)});
  }
};

template <>
struct action<g::draw_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [](auto it, auto end) {
      DrawStmt draw{box(take<Expr>(*it)), nullptr, std::nullopt};
      for (++it; it != end; ++it) {
        if (holds<Expr>(*it)) draw.transform = box(take<Expr>(*it));
        if (holds<PenClause>(*it)) draw.pen = take<PenClause>(*it);
      }
      return draw;
    });
  }
};

template <>
struct action<g::camera_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [](auto it, auto) {
      return CameraStmt{take<Name>(it[0]), box(take<Expr>(it[1]))};
    });
  }
};

template <>
struct action<g::animate_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [](auto it, auto end) {
      return AnimateStmt{box(take<Expr>(it[0])), optional_expr(it + 1, end)};
    });
  }
};

// A name as written, or a string's text: built-in profile names have dashes ("roland-dxy").
template <>
struct action<g::output_plotter_name> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    if (child_count(s) == 0) {
      s.items.emplace_back(PlotterName{Name{std::string(in.string_view()), span_of(in, s)}});
      return;
    }
    const Expr text = take<Expr>(s.items.back());
    const auto& lit = std::get<StringLit>(text.node);
    if (!lit.is_plain()) {
      throw SyntaxError{in.begin(), "the plotter name must be a plain string, without '{...}'",
                        "write the name as it is, as in 'plotter \"roland-dxy\"'"};
    }
    replace_children(s, PlotterName{Name{lit.plain_text(), text.span}});
  }
};

template <>
struct action<g::output_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [](auto it, auto end) {
      OutputStmt output{box(take<Expr>(it[0])), {}, std::nullopt};
      if (end != it + 1 && holds<PlotterName>(*(end - 1))) {
        output.plotter = take<PlotterName>(*(end - 1)).name;
        --end;
      }
      output.paper = paper_spec(it + 1, end);
      return output;
    });
  }
};

template <>
struct action<g::paper_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [](auto it, auto end) { return PaperStmt{paper_spec(it, end)}; });
  }
};

template <>
struct action<g::style_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [](auto it, auto end) {
      StyleStmt style{take<Name>(it[0]), take<Name>(it[1]), nullptr, std::nullopt};
      for (it += 2; it != end; ++it) {
        if (holds<PenClause>(*it))
          style.pen = take<PenClause>(*it);
        else
          style.levels = box(take<Expr>(*it));  // levels N
      }
      return style;
    });
  }
};

template <>
struct action<g::pen_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [](auto it, auto end) {
      PenStmt pen{box(take<Expr>(*it)), {}};
      for (++it; it != end; ++it) pen.options.push_back(take<Argument>(*it));
      return pen;
    });
  }
};

template <>
struct action<g::plotter_entry> : make_argument {};

template <>
struct action<g::plotter_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [](auto it, auto end) {
      PlotterStmt plotter{take<Name>(*it), {}};
      for (++it; it != end; ++it) plotter.entries.push_back(take<Argument>(*it));
      return plotter;
    });
  }
};

template <>
struct action<g::label_on_page> {
  template <typename Input>
  static void apply(const Input&, ParseState& s) {
    s.items.emplace_back(PageMarker{});
  }
};

template <>
struct action<g::label_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [](auto it, auto end) {
      LabelStmt label;
      label.text = box(take<Expr>(*it++));
      if (holds<PageMarker>(*it)) {
        label.on_page = true;
        ++it;
      }
      label.point = box(take<Expr>(*it++));
      if (it != end && holds<PenClause>(*(end - 1))) label.pen = take<PenClause>(*--end);
      if (it != end) label.size = box(take<Expr>(*it++));
      return label;
    });
  }
};

template <>
struct action<g::view_option> : make_argument {};

template <>
struct action<g::view_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [](auto it, auto end) {
      ViewStmt view;
      view.name = take<Name>(*it++);
      view.camera = box(take<Expr>(*it++));
      view.point = box(take<Expr>(*it++));
      for (; it != end; ++it) view.options.push_back(take<Argument>(*it));
      return view;
    });
  }
};

template <>
struct action<g::views_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [](auto it, auto end) {
      ViewsStmt views;
      views.object = box(take<Expr>(*it++));
      for (; it != end; ++it) views.options.push_back(take<Argument>(*it));
      return views;
    });
  }
};

template <>
struct action<g::dimension_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [](auto it, auto end) {
      DimensionStmt dimension;
      // An angle has three points before the view's name and the options, a distance two.
      int points = 0;
      for (auto j = it; j != end && holds<Expr>(*j); ++j) ++points;
      if (points == 3) dimension.vertex = box(take<Expr>(*it++));
      dimension.from = box(take<Expr>(*it++));
      dimension.to = box(take<Expr>(*it++));
      if (it != end && holds<Name>(*it)) dimension.view = take<Name>(*it++);
      for (; it != end; ++it) dimension.options.push_back(take<Argument>(*it));
      return dimension;
    });
  }
};

template <>
struct action<g::include_path> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    const auto& lit = std::get<StringLit>(std::get<Expr>(s.items.back()).node);
    if (!lit.is_plain()) {
      throw SyntaxError{in.begin(), "the file name after 'include' must be a plain string, without '{...}'",
                        "includes are read before the script runs, so nothing can be interpolated"};
    }
  }
};

template <>
struct action<g::include_stmt> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    make_statement(span_of(in, s), s, [](auto it, auto) {
      Expr path = take<Expr>(it[0]);
      return IncludeStmt{std::get<StringLit>(path.node).plain_text(), path.span};
    });
  }
};

}  // namespace

StatementParse parse_statement(const SourceFile& file, std::size_t offset, ParseState& state) {
  state.file = &file;
  state.base = file.text().data();
  state.items.clear();
  state.marks.clear();
  state.openers.clear();
  state.prefix_depth = 0;
  state.last_failed_at = nullptr;
  tao::pegtl::memory_input<tao::pegtl::tracking_mode::lazy> in(state.base + offset,
                                                               state.base + file.text().size(), file.name());
  StatementParse result;
  try {
    (void)tao::pegtl::parse<tao::pegtl::must<g::top_statement>, action, control>(in, state);
    result.statement = std::get<Stmt>(std::move(state.items.back()));
    result.end = state.offset(in.current());
  } catch (const SyntaxError& error) {
    result.error = error;
  }
  return result;
}

}  // namespace hlr::lang::detail
