// The hlrscript grammar (PEGTL 3.2), read top to bottom: padding and comments, keywords, literals,
// expressions one precedence level per rule, solid bodies, statements, and the script.
//
// Padding rule: a rule eats the padding *inside* it and never the padding around it. Sequences put
// `sp` between their elements; no rule begins or ends with `sp`. So a rule's match is exactly its
// text (the AST spans come from it), and a failing `must<>` points at the next token, not at the
// whitespace before it. Padding is spaces, tabs, newlines and `#` comments: newlines carry no
// meaning. Statements need no separator because each one starts with a keyword; `for i in 0..4 {
// draw post(1 + i) at translate(2*i, 0, 0) }` on one line is the same as spread over three.
//
// Aliases: a rule that stands for another in one place (to get its own error message) is written
// `struct add_rhs : seq< mul_expr > {}`, never by deriving, so that mul_expr's action still runs.
//
// Commit points: after a statement keyword (and after `(`, `[`, `{`, an operator, ...) the rest is
// wrapped in `must<>`: a failure there raises an error at that spot instead of backtracking. Each
// rule under `must<>` is its own struct with its own message in grammar_errors.hpp, so the message
// names the context ("expected '=' after the vertex id"). Nothing outside `must<>` has a message.
//
// Precedence, lowest first (one rule per level):
//   then_expr   a then b            transform composition, left-assoc
//   or_expr     a or b              left-assoc
//   and_expr    a and b             left-assoc
//   not_expr    not a               prefix (so `not a == b` is `not (a == b)`)
//   cmp_expr    == != < <= > >=     non-associative: `a < b < c` is an error
//   range_expr  a..b                non-associative
//   add_expr    + -                 left-assoc
//   mul_expr    * / %               left-assoc
//   neg_expr    -a                  prefix
//   postfix     f(x, k: v)  v.x  l[0]
//   primary     number string true false (x, y, z) (e) [a, b] [e for x in l if c] name
//
// Solids: `solid NAME [(OPTION: EXPR, ...)] { vertex ... face ... hole ... line ... }`.
// Option lists `(NAME: EXPR, ...)` after a solid's name, a paper size and a pen number share one shape
// (option_list), each with its own commit points and messages.
//
// Reserved words (never names): solid let def return for in if else draw at camera animate output
// paper style include then and or not true false. Words with meaning in one place only stay free
// as names elsewhere: vertex face hole line (inside a solid), frames fps (after animate),
// landscape portrait (after a paper size), hidden dashed off levels (after style), pen plotter (at a
// statement's start — no statement starts with an expression — and in `draw ... pen N`, `style hidden
// dashed pen N`, `output ... plotter NAME`). Where such a clause could also be the next statement
// (`draw a` then `pen 2 (colour: "red")`), a lookahead for the statement's shape decides.
#pragma once

#include <tao/pegtl.hpp>

#include <algorithm>
#include <string_view>
#include <type_traits>

#include "lang/plain_expression.hpp"
#include "lang/plain_solid_item.hpp"

namespace hlr::lang::grammar {

using namespace tao::pegtl;  // NOLINT: the grammar reads as PEG, as in PEGTL's own examples

// clang-format off

// ---- padding and comments -----------------------------------------------------------------------

struct comment : seq< one< '#' >, until< eolf > > {};
struct blank : one< ' ', '\t', '\r', '\n', '\f', '\v' > {};
struct sp : star< sor< blank, comment > > {};

// ---- identifiers and keywords -------------------------------------------------------------------

struct identifier_first : ranges< 'a', 'z', 'A', 'Z', '_' > {};
struct identifier_other : ranges< 'a', 'z', 'A', 'Z', '0', '9', '_' > {};
struct identifier : seq< identifier_first, star< identifier_other > > {};

template< typename Word > struct key : seq< Word, not_at< identifier_other > > {};

struct key_solid : key< TAO_PEGTL_STRING( "solid" ) > {};
struct key_let : key< TAO_PEGTL_STRING( "let" ) > {};
struct key_def : key< TAO_PEGTL_STRING( "def" ) > {};
struct key_return : key< TAO_PEGTL_STRING( "return" ) > {};
struct key_for : key< TAO_PEGTL_STRING( "for" ) > {};
struct key_in : key< TAO_PEGTL_STRING( "in" ) > {};
struct key_if : key< TAO_PEGTL_STRING( "if" ) > {};
struct key_else : key< TAO_PEGTL_STRING( "else" ) > {};
struct key_draw : key< TAO_PEGTL_STRING( "draw" ) > {};
struct key_at : key< TAO_PEGTL_STRING( "at" ) > {};
struct key_camera : key< TAO_PEGTL_STRING( "camera" ) > {};
struct key_animate : key< TAO_PEGTL_STRING( "animate" ) > {};
struct key_output : key< TAO_PEGTL_STRING( "output" ) > {};
struct key_paper : key< TAO_PEGTL_STRING( "paper" ) > {};
struct key_style : key< TAO_PEGTL_STRING( "style" ) > {};
struct key_include : key< TAO_PEGTL_STRING( "include" ) > {};
struct key_then : key< TAO_PEGTL_STRING( "then" ) > {};
struct key_and : key< TAO_PEGTL_STRING( "and" ) > {};
struct key_or : key< TAO_PEGTL_STRING( "or" ) > {};
struct key_not : key< TAO_PEGTL_STRING( "not" ) > {};
struct key_true : key< TAO_PEGTL_STRING( "true" ) > {};
struct key_false : key< TAO_PEGTL_STRING( "false" ) > {};

// clang-format on

// The text of a keyword rule: "solid" for key_solid.
template <char... Cs>
inline constexpr char kWordText[] = {Cs...};
template <char... Cs>
constexpr std::string_view word_of(const key<ascii::string<Cs...>>*) {
  return {kWordText<Cs...>, sizeof...(Cs)};
}

// One of the keywords Keys, whole — what sor< Keys... > matches — found by reading the identifier once and
// looking it up rather than by trying each word in turn: `reserved` runs before every name. To the
// grammar's analysis it is an `identifier` (it matches the same text or none).
template <typename... Keys>
struct any_word : identifier {
  // Whether `word` (a whole identifier) is one of the keywords.
  static bool contains(std::string_view word) {
    static constexpr std::string_view kWords[] = {word_of(static_cast<const Keys*>(nullptr))...};
    static constexpr std::size_t kShortest = std::min({word_of(static_cast<const Keys*>(nullptr)).size()...});
    static constexpr std::size_t kLongest = std::max({word_of(static_cast<const Keys*>(nullptr)).size()...});
    if (word.size() < kShortest || word.size() > kLongest) return false;  // most names: no comparing
    for (const std::string_view w : kWords)
      if (w == word) return true;
    return false;
  }
  template <typename ParseInput>
  [[nodiscard]] static bool match(ParseInput& in) {
    const char* const begin = in.current();
    const char* p = begin;
    while (p < in.end() && ((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') || (*p >= '0' && *p <= '9') ||
                            *p == '_'))
      ++p;
    const std::string_view word(begin, static_cast<std::size_t>(p - begin));
    if (!contains(word)) return false;
    in.bump(word.size());
    return true;
  }
};

// clang-format off

struct reserved : any_word< key_solid, key_let, key_def, key_return, key_for, key_in, key_if, key_else, key_draw,
                            key_at, key_camera, key_animate, key_output, key_paper, key_style, key_include,
                            key_then, key_and, key_or, key_not, key_true, key_false > {};

// Contextual words: keywords only where they appear.
struct key_vertex : key< TAO_PEGTL_STRING( "vertex" ) > {};
struct key_face : key< TAO_PEGTL_STRING( "face" ) > {};
struct key_hole : key< TAO_PEGTL_STRING( "hole" ) > {};
struct key_line : key< TAO_PEGTL_STRING( "line" ) > {};
struct key_fps : key< TAO_PEGTL_STRING( "fps" ) > {};
struct key_landscape : key< TAO_PEGTL_STRING( "landscape" ) > {};
struct key_portrait : key< TAO_PEGTL_STRING( "portrait" ) > {};
struct key_pen : key< TAO_PEGTL_STRING( "pen" ) > {};
struct key_plotter : key< TAO_PEGTL_STRING( "plotter" ) > {};
struct key_label : key< TAO_PEGTL_STRING( "label" ) > {};
struct key_size : key< TAO_PEGTL_STRING( "size" ) > {};
struct key_page : key< TAO_PEGTL_STRING( "page" ) > {};
struct key_view : key< TAO_PEGTL_STRING( "view" ) > {};
struct key_dimension : key< TAO_PEGTL_STRING( "dimension" ) > {};
struct key_from : key< TAO_PEGTL_STRING( "from" ) > {};
struct key_to : key< TAO_PEGTL_STRING( "to" ) > {};
struct key_angle : key< TAO_PEGTL_STRING( "angle" ) > {};
struct key_views : key< TAO_PEGTL_STRING( "views" ) > {};
struct key_of : key< TAO_PEGTL_STRING( "of" ) > {};
struct solid_word : sor< key_vertex, key_face, key_hole, key_line > {};

struct name : seq< not_at< reserved >, identifier > {};

// ---- literals -----------------------------------------------------------------------------------

struct digits : plus< digit > {};
struct fraction : seq< one< '.' >, digits > {};
struct exponent_digits : digits {};
struct exponent : seq< one< 'e', 'E' >, opt< one< '+', '-' > >, must< exponent_digits > > {};
struct number_single_point : not_at< one< '.' >, digit > {};   // 1.2.3
struct number_no_letter : not_at< identifier_other > {};         // 2x
struct number : seq< digits, opt< fraction >, opt< exponent >, must< number_single_point, number_no_letter > > {};

struct bool_lit : sor< key_true, key_false > {};

struct expression;

struct escape_char : one< '"', '\\', 'n', 't', '{', '}' > {};
struct escape : seq< one< '\\' >, must< escape_char > > {};
struct string_text : plus< not_one< '"', '\\', '{', '\n', '\r' > > {};
struct interp_open : one< '{' > {};
struct interp_expr : seq< expression > {};
struct interp_format : star< not_one< '}', '"', '\n', '\r' > > {};
struct interp_close : one< '}' > {};
struct interpolation : seq< interp_open, sp, must< interp_expr >, sp, opt< one< ':' >, interp_format >, must< interp_close > > {};
struct string_open : one< '"' > {};
struct string_close : one< '"' > {};
struct string_lit : seq< string_open, star< sor< string_text, escape, interpolation > >, must< string_close > > {};

// ---- expressions, one rule per precedence level (lowest last) -----------------------------------

struct paren_open : one< '(' > {};
struct group_close : one< ')' > {};
struct vector_second : seq< expression > {};
struct vector_comma : one< ',' > {};
struct vector_third : seq< expression > {};
struct vector_close : one< ')' > {};
struct vector_end : one< ')' > {};  // (x, y): the point (x, y, 0)
struct vector_tail : seq< one< ',' >, sp, must< vector_second >, sp,
                          sor< seq< vector_comma, sp, must< vector_third >, sp, must< vector_close > >, must< vector_end > > > {};
struct paren_first : seq< expression > {};
struct paren_expr : seq< paren_open, sp, must< paren_first >, sp, sor< vector_tail, must< group_close > > > {};

struct list_open : one< '[' > {};
struct list_item : seq< expression > {};
struct list_next_item : seq< list_item > {};
struct list_close : one< ']' > {};
// After the first item: a `for` clause (a comprehension, `[EXPR for NAME in ITERABLE]` or with
// `if COND`), or more items. One rule, so the first item is parsed once, however deep lists nest.
struct comp_variable : name {};
struct comp_in : key_in {};
struct comp_iterable : seq< expression > {};
struct comp_condition : seq< expression > {};
struct comp_filter : seq< key_if, sp, must< comp_condition > > {};
struct comp_close : one< ']' > {};
struct comp_for : seq< key_for, sp, must< comp_variable >, sp, must< comp_in >, sp, must< comp_iterable >, opt< sp, comp_filter >, sp, must< comp_close > > {};
struct list_rest : seq< star< one< ',' >, sp, must< list_next_item >, sp >, must< list_close > > {};
struct list_lit : seq< list_open, sp, sor< seq< list_item, sp, sor< comp_for, list_rest > >, must< list_close > > > {};

struct name_ref : name {};
struct primary : sor< number, string_lit, bool_lit, paren_expr, list_lit, name_ref > {};

struct arg_label : seq< name, sp, one< ':' > > {};
struct labeled_value : seq< expression > {};
struct argument : sor< seq< arg_label, sp, must< labeled_value > >, expression > {};
struct next_argument : seq< argument > {};
struct arguments : seq< argument, star< sp, one< ',' >, sp, must< next_argument > > > {};
struct call_open : one< '(' > {};
struct call_close : one< ')' > {};
struct call_suffix : seq< call_open, sp, opt< arguments, sp >, must< call_close > > {};
struct member_name : name {};
struct member_suffix : seq< one< '.' >, not_at< one< '.' > >, sp, must< member_name > > {};
struct index_open : one< '[' > {};
struct index_value : seq< expression > {};
struct index_close : one< ']' > {};
struct index_suffix : seq< index_open, sp, must< index_value >, sp, must< index_close > > {};
struct postfix_expr : seq< primary, star< sp, sor< call_suffix, member_suffix, index_suffix > > > {};

// `(NAME: EXPR, ...)` after a solid's name, a paper size or a pen number: a call's argument list (the
// same `argument` rule, so positional values parse too and the runtime reports them) whose commit
// points are each place's own rules, for messages naming the place.
template< typename Open, typename Next, typename Close >
struct option_list : seq< Open, sp, opt< argument, star< sp, one< ',' >, sp, must< Next > >, sp >, must< Close > > {};

struct neg_op : one< '-' > {};
struct neg_operand;
struct neg_expr : sor< seq< neg_op, sp, must< neg_operand > >, postfix_expr > {};
struct neg_operand : seq< neg_expr > {};

struct mul_op : one< '*', '/', '%' > {};
struct mul_rhs : seq< neg_expr > {};
struct mul_expr : seq< neg_expr, star< sp, mul_op, sp, must< mul_rhs > > > {};

struct add_op : one< '+', '-' > {};
struct add_rhs : seq< mul_expr > {};
struct add_expr : seq< mul_expr, star< sp, add_op, sp, must< add_rhs > > > {};

struct range_op : two< '.' > {};
struct range_rhs : seq< add_expr > {};
struct range_single : not_at< sp, range_op > {};
struct range_expr : seq< add_expr, opt< sp, range_op, sp, must< range_rhs >, must< range_single > > > {};

struct cmp_op : sor< two< '=' >, string< '!', '=' >, string< '<', '=' >, string< '>', '=' >, one< '<' >, one< '>' > > {};
struct cmp_rhs : seq< range_expr > {};
struct cmp_single : not_at< sp, cmp_op > {};
struct cmp_expr : seq< range_expr, opt< sp, cmp_op, sp, must< cmp_rhs >, must< cmp_single > > > {};

struct not_op : key_not {};
struct not_operand;
struct not_expr : sor< seq< not_op, sp, must< not_operand > >, cmp_expr > {};
struct not_operand : seq< not_expr > {};

struct and_op : key_and {};
struct and_rhs : seq< not_expr > {};
struct and_expr : seq< not_expr, star< sp, and_op, sp, must< and_rhs > > > {};

struct or_op : key_or {};
struct or_rhs : seq< and_expr > {};
struct or_expr : seq< and_expr, star< sp, or_op, sp, must< or_rhs > > > {};

struct then_op : key_then {};
struct then_rhs : seq< or_expr > {};
struct then_expr : seq< or_expr, star< sp, then_op, sp, must< then_rhs > > > {};

// clang-format on

// A rule read by hand: `Read::into(in, state)` reads it and returns true, or declines (false) and leaves
// the text to `Twin`, which reads it to the same nodes; so to the grammar's analysis it is a Twin. Only
// when the parser builds nodes (the action of `Built`, a rule among Twin's, is on: not in the grammar
// tests, not in lookaheads) and with the parser's one state.
template <typename Twin, typename Built, typename Read>
struct read_by_hand : Twin {
  template <apply_mode A, rewind_mode, template <typename...> class Action, template <typename...> class,
            typename ParseInput, typename... States>
  [[nodiscard]] static bool match(ParseInput& in, States&... states) {
    if constexpr (A == apply_mode::action && !std::is_base_of_v<nothing<Built>, Action<Built>> &&
                  sizeof...(States) == 1) {
      return (Read::into(in, states) && ...);
    } else {
      return false;
    }
  }
};

// An expression read by hand (plain_expression.hpp) and pushed whole: the cascade above costs a rule
// attempt per level for every operand, and general code is mostly expressions. The reader builds the
// same nodes with the same spans, and leaves anything else (string interpolation, and every mistake,
// so the grammar reports it) to then_expr.
struct expression_reader {
  template <typename ParseInput, typename State>
  static bool into(ParseInput& in, State& state) {
    if constexpr (requires { state.items; state.file; state.base; state.plain_expressions; }) {
      if (!state.plain_expressions || !state.file) return false;
      Expr expr;
      const std::size_t length = lang::read_plain_expression(state.base, in.current(), in.end(), state.file->id(),
                                                             state.prefix_depth + state.openers.size(), expr);
      if (length == 0) return false;
      in.bump(length);
      state.items.emplace_back(std::move(expr));
      return true;
    } else {
      return false;
    }
  }
};
struct plain_expression : read_by_hand< then_expr, then_expr, expression_reader > {};

// clang-format off
struct expression : sor< plain_expression, then_expr > {};

// ---- solid bodies -------------------------------------------------------------------------------

struct id_number : seq< digits, not_at< identifier_other > > {};
struct id_name : seq< not_at< solid_word >, name > {};
struct vertex_id : sor< id_number, id_name > {};
struct vertex_decl_id : seq< vertex_id > {};
struct vertex_eq : seq< one< '=' >, not_at< one< '=' > > > {};
// A position written as three plain numbers on one line, `(1.5, -2, 0)`, and followed by the next item or
// the body's end, is read straight into the declaration (solid_body.hpp, SolidBody::Vertex::at) without building
// an expression: generated scripts are mostly this. Anything else — `(1, 2, 3) + v`, names, spaces after
// a minus — is an expression.
struct literal_blanks : star< one< ' ', '\t' > > {};
struct literal_number : seq< opt< one< '-' > >, digits, opt< fraction >, opt< exponent >, must< number_single_point, number_no_letter > > {};
struct literal_position : seq< one< '(' >, literal_blanks, literal_number, literal_blanks, one< ',' >, literal_blanks, literal_number, literal_blanks, one< ',' >, literal_blanks, literal_number, literal_blanks, one< ')' >, at< sp, sor< key_vertex, key_face, key_line, one< '}' > > > > {};
struct vertex_position : sor< literal_position, expression > {};
struct vertex_decl : seq< key_vertex, sp, must< vertex_decl_id >, sp, must< vertex_eq >, sp, must< vertex_position > > {};

struct face_ids : seq< vertex_id, star< sp, vertex_id > > {};
struct hole_ids : seq< face_ids > {};
struct hole_clause : seq< key_hole, sp, must< hole_ids > > {};
struct face_decl : seq< key_face, sp, must< face_ids >, star< sp, hole_clause > > {};

struct line_from : seq< vertex_id > {};
struct line_to : seq< vertex_id > {};
struct line_decl : seq< key_line, sp, must< line_from >, sp, must< line_to > > {};

// Build options between the name and '{': `solid hull (crease: 30, planarity: 0.003) { ... }`. The list
// is a call's argument list (the same `argument` rule, so positional values parse too and the runtime
// reports them) with its own commit points and messages.
struct solid_options_open : one< '(' > {};
struct solid_option_next : seq< argument > {};
struct solid_options_close : one< ')' > {};
struct solid_options : option_list< solid_options_open, solid_option_next, solid_options_close > {};

struct solid_item : sor< vertex_decl, face_decl, line_decl > {};
struct solid_words : any_word< key_vertex, key_face, key_hole, key_line > {};

// clang-format on

// A solid item in its plainest form — `vertex ID = (x, y, z)` as literal_position takes it, `face ID ID ...`
// without holes, `line ID ID` — read by hand (plain_solid_item.hpp) straight into the block being parsed:
// generated scripts are mostly this, and at a rule attempt per character the grammar reads them at a
// quarter of the speed. Anything else, errors included, it leaves to solid_item, which reads the same
// text to the same items.
struct solid_item_reader {
  template <typename ParseInput, typename State>
  static bool into(ParseInput& in, State& state) {
    if constexpr (requires { state.solid.file(); state.base; state.plain_solid_items; }) {
      if (!state.plain_solid_items) return false;
      const std::size_t length = lang::read_plain_solid_item(state.base, in.current(), in.end(), state.solid);
      in.bump(length);
      return length > 0;
    } else {
      return false;
    }
  }
};
struct plain_solid_item : read_by_hand< solid_item, vertex_decl, solid_item_reader > {};

// clang-format off
struct solid_name : name {};
struct solid_open : one< '{' > {};
struct solid_close : one< '}' > {};
struct solid_stmt : seq< key_solid, sp, must< solid_name >, sp, opt< solid_options, sp >, must< solid_open >, sp, star< sor< plain_solid_item, solid_item >, sp >, must< solid_close > > {};

// ---- statements ---------------------------------------------------------------------------------

struct statement;

struct block_open : one< '{' > {};
struct block_close : one< '}' > {};
struct block : seq< block_open, sp, star< statement, sp >, must< block_close > > {};

struct let_name : name {};
struct let_eq : seq< one< '=' >, not_at< one< '=' > > > {};
struct let_value : seq< expression > {};
struct let_stmt : seq< key_let, sp, must< let_name >, sp, must< let_eq >, sp, must< let_value > > {};

struct def_name : name {};
struct params_open : one< '(' > {};
struct param_name : name {};
struct param_default : seq< expression > {};
struct param : seq< param_name, opt< sp, one< '=' >, sp, must< param_default > > > {};
struct next_param : seq< param > {};
struct params : seq< param, star< sp, one< ',' >, sp, must< next_param > > > {};
struct params_close : one< ')' > {};
struct def_value : seq< expression > {};
struct def_block : seq< block > {};
struct def_body : sor< seq< one< '=' >, sp, must< def_value > >, def_block > {};
struct def_stmt : seq< key_def, sp, must< def_name >, sp, must< params_open >, sp, opt< params, sp >, must< params_close >, sp, must< def_body > > {};

struct return_value : seq< expression > {};
struct return_stmt : seq< key_return, opt< sp, return_value > > {};

struct for_variable : name {};
struct for_in : key_in {};
struct for_iterable : seq< expression > {};
struct for_body : seq< block > {};
struct for_stmt : seq< key_for, sp, must< for_variable >, sp, must< for_in >, sp, must< for_iterable >, sp, must< for_body > > {};

struct if_stmt;
struct if_condition : seq< expression > {};
struct if_body : seq< block > {};
struct else_body : sor< if_stmt, block > {};
struct if_stmt : seq< key_if, sp, must< if_condition >, sp, must< if_body >, opt< sp, key_else, sp, must< else_body > > > {};

// `pen N` after a draw or `style hidden dashed|levels N`; not when it is the start of a pen statement, `pen N (`
// followed by `)` or `NAME:` (N a number, a name or a parenthesised expression, as in pen_stmt).
struct pen_number : sor< number, name_ref, seq< not_at< one< '(' >, sp, arg_label >, paren_expr > > {};
struct pen_stmt_ahead : seq< key_pen, sp, pen_number, sp, one< '(' >, sp, sor< one< ')' >, arg_label > > {};
struct pen_value : seq< expression > {};
struct pen_clause : seq< not_at< pen_stmt_ahead >, key_pen, sp, must< pen_value > > {};

struct draw_object : seq< expression > {};
struct draw_transform : seq< expression > {};
struct draw_stmt : seq< key_draw, sp, must< draw_object >, opt< sp, key_at, sp, must< draw_transform > >, opt< sp, pen_clause > > {};

struct camera_name : name {};
struct camera_eq : seq< one< '=' >, not_at< one< '=' > > > {};
struct camera_value : seq< expression > {};
struct camera_stmt : seq< key_camera, sp, must< camera_name >, sp, must< camera_eq >, sp, must< camera_value > > {};

struct animate_frames : key< TAO_PEGTL_STRING( "frames" ) > {};
struct frame_count : seq< expression > {};
struct fps_value : seq< expression > {};
struct animate_stmt : seq< key_animate, sp, must< animate_frames >, sp, must< frame_count >, opt< sp, key_fps, sp, must< fps_value > > > {};

// paper SIZE [landscape|portrait] [(margin: MM, scale: MM_PER_UNIT)]; SIZE `custom` takes width: and
// height: in the options. The same after `output "..."`, which also takes a lone orientation (kept from
// before papers had options) and `plotter NAME` (a name, or a string for built-in names with dashes).
struct paper_size : identifier {};
struct orientation : sor< key_landscape, key_portrait > {};
struct paper_options_open : one< '(' > {};
struct paper_option_next : seq< argument > {};
struct paper_options_close : one< ')' > {};
struct paper_options : option_list< paper_options_open, paper_option_next, paper_options_close > {};
struct output_pattern : seq< string_lit > {};
struct output_paper_size : seq< paper_size > {};
struct output_paper : seq< key_paper, sp, must< output_paper_size >, opt< sp, orientation >, opt< sp, paper_options > > {};
struct plotter_stmt_ahead : seq< key_plotter, sp, name, sp, one< '{' > > {};
struct output_plotter_name : sor< string_lit, name > {};
struct output_plotter : seq< not_at< plotter_stmt_ahead >, key_plotter, sp, must< output_plotter_name > > {};
struct output_stmt : seq< key_output, sp, must< output_pattern >, opt< sp, sor< output_paper, orientation > >, opt< sp, output_plotter > > {};
struct paper_stmt : seq< key_paper, sp, must< paper_size >, opt< sp, orientation >, opt< sp, paper_options > > {};

// style hidden dashed|off|levels N [pen P]; N an expression, as a pen clause's number — but not `pen P`
// itself, so that a forgotten N is reported at the pen rather than read as a variable named pen.
struct style_property : key< TAO_PEGTL_STRING( "hidden" ) > {};
struct style_word : sor< key< TAO_PEGTL_STRING( "dashed" ) >, key< TAO_PEGTL_STRING( "off" ) > > {};
struct style_levels_word : key< TAO_PEGTL_STRING( "levels" ) > {};
struct levels_count : seq< not_at< key_pen, sp, pen_number >, expression > {};
struct style_value : sor< style_word, seq< style_levels_word, sp, must< levels_count > > > {};
struct style_stmt : seq< key_style, sp, must< style_property >, sp, must< style_value >, opt< sp, pen_clause > > {};

// pen N (colour: "red", width: 0.35). N is a number, a name or a parenthesised expression — not a
// call, whose '(' would take the options.
struct pen_options_open : one< '(' > {};
struct pen_option_next : seq< argument > {};
struct pen_options_close : one< ')' > {};
struct pen_options : option_list< pen_options_open, pen_option_next, pen_options_close > {};
struct pen_stmt : seq< key_pen, sp, must< pen_number >, sp, must< pen_options > > {};

// plotter NAME { KEY: EXPR ... }: entries separated by ',' or just padding (one per line).
struct plotter_name : name {};
struct plotter_open : one< '{' > {};
struct plotter_value : seq< expression > {};
struct plotter_entry : seq< arg_label, sp, must< plotter_value > > {};
struct plotter_next_entry : seq< plotter_entry > {};
struct plotter_entries : seq< plotter_entry, star< sp, sor< seq< one< ',' >, sp, must< plotter_next_entry > >, plotter_entry > > > {};
struct plotter_close : one< '}' > {};
struct plotter_stmt : seq< key_plotter, sp, must< plotter_name >, sp, must< plotter_open >, sp, opt< plotter_entries, sp >, must< plotter_close > > {};

// label TEXT at POINT [size: MM] [pen N]: TEXT in single-stroke letters, POINT (x, y, z) in the world
// (projected and hidden as the solids are) or `page (x, y)`, millimetres from the page's top-left corner.
struct label_text : seq< expression > {};
struct label_at : key_at {};
struct label_on_page : seq< key_page, at< sp, one< '(' > > > {};
struct label_point : seq< expression > {};
struct label_where : seq< opt< label_on_page, sp >, must< label_point > > {};
struct label_size_value : seq< expression > {};
struct label_size : seq< key_size, sp, one< ':' >, sp, must< label_size_value > > {};
struct label_stmt : seq< key_label, sp, must< label_text >, sp, must< label_at >, sp, label_where,
                         opt< sp, label_size >, opt< sp, pen_clause > > {};

// view NAME = CAMERA at page (X, Y) [KEY: EXPR ...]: the camera's drawing placed on the sheet, its picture
// origin at page millimetres (X, Y); options (scale:, label:, hidden:) follow as `key: value`, no commas.
struct view_name : name {};
struct view_camera : seq< expression > {};
struct view_at : key_at {};
struct view_page : key_page {};
struct view_point : seq< expression > {};
struct view_option_value : seq< expression > {};
struct view_option : seq< arg_label, sp, must< view_option_value > > {};
struct view_stmt : seq< key_view, sp, must< view_name >, sp, must< camera_eq >, sp, must< view_camera >, sp,
                        must< view_at >, sp, must< view_page >, sp, must< view_point >, star< sp, view_option > > {};

// views of PART [KEY: EXPR ...]: the standard views of a part — front, top and a side view placed in first-
// or third-angle projection, and an isometric one — laid out on the sheet by the scale fit; options
// (projection:, iso:, scale:, gap:, hidden:) as a view's. `views` is a keyword only before `of`.
struct views_object : seq< expression > {};
struct views_stmt : seq< key_views, sp, key_of, sp, must< views_object >, star< sp, view_option > > {};

// dimension [angle at V] from P to Q [in VIEW] [KEY: EXPR ...]: the distance between two world points, or
// the angle P V Q, drawn in a view of the sheet; options (offset:, direction:, radius:, text:, precision:,
// unit:, pen:) as a view's.
struct dimension_angle_at : key_at {};
struct dimension_vertex : seq< expression > {};
struct dimension_angle : seq< key_angle, sp, must< dimension_angle_at >, sp, must< dimension_vertex > > {};
struct dimension_from : key_from {};
struct dimension_start : seq< expression > {};
struct dimension_to : key_to {};
struct dimension_end : seq< expression > {};
struct dimension_view : name {};
struct dimension_in : seq< key_in, sp, must< dimension_view > > {};
struct dimension_stmt : seq< key_dimension, sp, opt< dimension_angle, sp >, must< dimension_from >, sp, must< dimension_start >, sp,
                             must< dimension_to >, sp, must< dimension_end >, opt< sp, dimension_in >,
                             star< sp, view_option > > {};

struct include_path : seq< string_lit > {};
struct include_stmt : seq< key_include, sp, must< include_path > > {};

struct statement : sor< solid_stmt, let_stmt, def_stmt, return_stmt, for_stmt, if_stmt, draw_stmt, camera_stmt,
                        animate_stmt, output_stmt, paper_stmt, style_stmt, include_stmt, pen_stmt, plotter_stmt,
                        label_stmt, views_stmt, view_stmt, dimension_stmt > {};

// ---- the script ---------------------------------------------------------------------------------

// One statement at a time: the parser (parser.cpp) calls this once per statement so that it can
// resynchronise after an error and report the next one.
struct top_statement : statement {};
struct script : seq< sp, until< eof, must< top_statement >, sp > > {};

// clang-format on

}  // namespace hlr::lang::grammar
