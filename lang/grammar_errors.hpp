// What the grammar says when a `must<>` fails: one message per committed rule, in our words, each
// naming what was expected and where, with an example when the form is not obvious. The control
// (parse_control.hpp) static_asserts that every rule it can raise for has a message here, so none
// can be missing. An optional hint adds how to fix it.
//
// Beside the messages, four traits steer the control: which rules open and close brackets (so an
// unclosed '{' can say where it opened), which rules nest (depth limit), and which rules expect a
// name (so a reserved word in that place gets its own message).
#pragma once

#include "lang/grammar.hpp"

namespace hlr::lang::grammar {

template <typename Rule>
inline constexpr const char* error_message = nullptr;
template <typename Rule>
inline constexpr const char* error_hint = nullptr;

#define HLR_ERROR(rule, text) \
  template <>                 \
  inline constexpr const char* error_message<rule> = text
#define HLR_HINT(rule, text) \
  template <>                \
  inline constexpr const char* error_hint<rule> = text

// clang-format off

// ---- literals ----
HLR_ERROR(exponent_digits, "expected digits after the exponent 'e' of the number, as in '1.5e-3'");
HLR_ERROR(number_single_point, "malformed number: a number has at most one decimal point");
HLR_HINT(number_single_point, "write numbers as 12, 1.5 or 1.5e3");
HLR_ERROR(number_no_letter, "malformed number: a letter follows the digits");
HLR_HINT(number_no_letter, "names cannot start with a digit; to multiply, write '2 * x'");
HLR_ERROR(escape_char, "unknown escape in the string");
HLR_HINT(escape_char, "the escapes are \\\" \\\\ \\n \\t \\{ and \\}");
HLR_ERROR(interp_expr, "expected an expression inside '{...}' in the string");
HLR_HINT(interp_expr, "for a literal brace write '\\{'");
HLR_ERROR(interp_close, "expected '}' to end the '{...}' in the string, as in \"frame-{frame:03}.pdf\"");
HLR_ERROR(string_close, "unterminated string: add '\"' before the end of the line");

// ---- expressions ----
HLR_ERROR(paren_first, "expected an expression after '('");
HLR_ERROR(group_close, "expected ')' or ','");
HLR_HINT(group_close, "a parenthesised expression is '(a + b)', a vector '(x, y, z)', a point of the xy plane '(x, y)'");
HLR_ERROR(vector_second, "expected the second component of the vector after ','");
HLR_ERROR(vector_end, "expected ')' or ',' and a third component after the vector's second component");
HLR_HINT(vector_end, "(x, y) is the point (x, y, 0) of the xy plane, (x, y, z) a vector");
HLR_ERROR(vector_third, "expected the third component of the vector after ','");
HLR_ERROR(vector_close, "expected ')' after the third component: a vector has exactly three components");
HLR_ERROR(list_next_item, "expected a list element after ','");
HLR_HINT(list_next_item, "a trailing ',' is not allowed: write '[a, b]'");
HLR_ERROR(list_close, "expected ',' or ']' in the list");
HLR_ERROR(comp_variable, "expected the comprehension's variable after 'for', as in '[i * i for i in 0..10]'");
HLR_ERROR(comp_in, "expected 'in' after the comprehension's variable, as in '[i * i for i in 0..10]'");
HLR_ERROR(comp_iterable, "expected a range or list after 'in', as in '[i * i for i in 0..10]'");
HLR_ERROR(comp_condition, "expected a condition after 'if', as in '[i for i in 0..10 if i % 2 == 0]'");
HLR_ERROR(comp_close, "expected ']' to end the comprehension");
HLR_HINT(comp_close, "a comprehension has one 'for' and at most one 'if', as in '[i for i in 0..10 if i % 2 == 0]'; nest comprehensions for more");
HLR_ERROR(labeled_value, "expected a value after the argument name and ':', as in 'fov: 40'");
HLR_ERROR(next_argument, "expected an argument after ','");
HLR_HINT(next_argument, "a trailing ',' is not allowed: write 'f(a, b)'");
HLR_ERROR(call_close, "expected ',' or ')' in the argument list");
HLR_ERROR(member_name, "expected a member name after '.', as in 'v.x'");
HLR_ERROR(index_value, "expected an index after '[', as in 'l[0]'");
HLR_ERROR(index_close, "expected ']' after the index");
HLR_ERROR(neg_operand, "expected an operand after '-'");
HLR_ERROR(mul_rhs, "expected an operand after the operator");
HLR_ERROR(add_rhs, "expected an operand after the operator");
HLR_ERROR(range_rhs, "expected the end of the range after '..', as in '0..4'");
HLR_ERROR(range_single, "a range has one '..': write 'a..b'");
HLR_ERROR(cmp_rhs, "expected an operand after the comparison");
HLR_ERROR(cmp_single, "comparisons do not chain");
HLR_HINT(cmp_single, "write 'a < b and b < c'");
HLR_ERROR(not_operand, "expected an operand after 'not'");
HLR_ERROR(and_rhs, "expected an operand after 'and'");
HLR_ERROR(or_rhs, "expected an operand after 'or'");
HLR_ERROR(then_rhs, "expected a transform after 'then', as in 'rotate(z: 30) then scale(2)'");

// ---- solids ----
HLR_ERROR(solid_name, "expected a name after 'solid', as in 'solid box { ... }'");
HLR_ERROR(solid_open, "expected '{' after the solid's name");
HLR_HINT(solid_open, "write 'solid box { ... }', or with options 'solid box (crease: 30) { ... }'");
HLR_ERROR(solid_option_next, "expected an option after ',' in the solid's options, as in '(crease: 30, planarity: 0.003)'");
HLR_HINT(solid_option_next, "a trailing ',' is not allowed");
HLR_ERROR(solid_options_close, "expected ',' or ')' in the solid's options");
HLR_HINT(solid_options_close, "options are 'name: value' pairs separated by ',', as in 'solid hull (crease: 30, planarity: 0.003) { ... }'");
HLR_ERROR(solid_close, "expected 'vertex', 'face', 'line' or '}' in the solid");
HLR_ERROR(vertex_decl_id, "expected a vertex id (a whole number or a name) after 'vertex', as in 'vertex 1 = (0, 0, 0)'");
HLR_ERROR(vertex_eq, "expected '=' after the vertex id, as in 'vertex 1 = (0, 0, 0)'");
HLR_ERROR(vertex_position, "expected the vertex position after '=', as in 'vertex 1 = (0, 0, 0)'");
HLR_ERROR(face_ids, "expected vertex ids after 'face', as in 'face 1 2 3'");
HLR_ERROR(hole_ids, "expected vertex ids after 'hole', as in 'face 1 2 3 4 hole 5 6 7'");
HLR_ERROR(line_from, "expected two vertex ids after 'line', as in 'line 1 2'");
HLR_ERROR(line_to, "expected a second vertex id: a line joins two vertices, as in 'line 1 2'");

// ---- statements ----
HLR_ERROR(block_close, "expected a statement or '}'");
HLR_ERROR(let_name, "expected a name after 'let', as in 'let x = 1'");
HLR_ERROR(let_eq, "expected '=' after the name, as in 'let x = 1'");
HLR_ERROR(let_value, "expected a value after '=', as in 'let x = 1'");
HLR_ERROR(def_name, "expected a function name after 'def', as in 'def f(x) = x * 2'");
HLR_ERROR(params_open, "expected '(' and the parameters after the function name, as in 'def f(x) = x * 2'");
HLR_ERROR(next_param, "expected a parameter name after ','");
HLR_HINT(next_param, "a trailing ',' is not allowed: write 'def f(a, b) = ...'");
HLR_ERROR(param_default, "expected a default value after '=', as in 'def f(x, n = 6) = ...'");
HLR_ERROR(params_close, "expected a parameter name, ',' or ')' in the parameter list");
HLR_ERROR(def_body, "expected '= expression' or a '{ ... }' body after the parameters");
HLR_HINT(def_body, "write 'def f(x) = x * 2' or 'def f(x) { return x * 2 }'");
HLR_ERROR(def_value, "expected the function's expression after '='");
HLR_ERROR(for_variable, "expected the loop variable after 'for', as in 'for i in 0..4 { ... }'");
HLR_ERROR(for_in, "expected 'in' after the loop variable, as in 'for i in 0..4 { ... }'");
HLR_ERROR(for_iterable, "expected a range or list after 'in', as in 'for i in 0..4 { ... }'");
HLR_ERROR(for_body, "expected '{' to start the loop body");
HLR_ERROR(if_condition, "expected a condition after 'if'");
HLR_ERROR(if_body, "expected '{' after the condition");
HLR_ERROR(else_body, "expected '{' or 'if' after 'else'");
HLR_ERROR(draw_object, "expected what to draw after 'draw', as in 'draw box'");
HLR_ERROR(draw_transform, "expected a transform after 'at', as in 'draw box at translate(1, 0, 0)'");
HLR_ERROR(camera_name, "expected a camera name after 'camera', as in 'camera main = lookat(...)'");
HLR_ERROR(camera_eq, "expected '=' after the camera name, as in 'camera main = lookat(...)'");
HLR_ERROR(camera_value, "expected a camera after '=', as in 'camera main = orbit(theta: 45, phi: 60, rho: 425, d: 1549)'");
HLR_ERROR(animate_frames, "expected 'frames' after 'animate', as in 'animate frames 48 fps 12'");
HLR_ERROR(frame_count, "expected the number of frames after 'frames', as in 'animate frames 48'");
HLR_ERROR(fps_value, "expected frames per second after 'fps', as in 'animate frames 48 fps 12'");
HLR_ERROR(output_pattern, "expected a quoted file name after 'output', as in 'output \"frame-{frame:03}.pdf\"'");
HLR_ERROR(output_paper_size, "expected a paper size after 'paper', as in 'paper A4'");
HLR_ERROR(paper_size, "expected a paper size after 'paper', as in 'paper A4'");
HLR_ERROR(paper_option_next, "expected an option after ',' in the paper's options, as in '(margin: 10, scale: 0.5)'");
HLR_HINT(paper_option_next, "a trailing ',' is not allowed");
HLR_ERROR(paper_options_close, "expected ',' or ')' in the paper's options");
HLR_HINT(paper_options_close, "options are 'name: value' pairs separated by ',', as in 'paper A4 landscape (margin: 10, scale: 0.5)'");
HLR_ERROR(output_plotter_name, "expected a plotter name after 'plotter', as in 'plotter hp7475a' or 'plotter \"roland-dxy\"'");
HLR_ERROR(style_property, "expected 'hidden' after 'style', as in 'style hidden dashed'");
HLR_ERROR(style_value, "expected 'dashed', 'off' or 'levels N' after 'style hidden'");
HLR_ERROR(levels_count, "expected how many occlusion levels to draw after 'levels', as in 'style hidden levels 3'");
HLR_ERROR(pen_value, "expected a pen number after 'pen', as in 'draw box pen 2'");
HLR_ERROR(pen_number, "expected the pen number after 'pen', as in 'pen 2 (colour: \"red\", width: 0.35)'");
HLR_HINT(pen_number, "the number is a whole number, a name or an expression in parentheses: 'pen (i + 1) (...)'");
HLR_ERROR(pen_options, "expected '(' and the pen's options after the pen number, as in 'pen 2 (colour: \"red\", width: 0.35)'");
HLR_ERROR(pen_option_next, "expected an option after ',' in the pen's options, as in '(colour: \"red\", width: 0.35)'");
HLR_HINT(pen_option_next, "a trailing ',' is not allowed");
HLR_ERROR(pen_options_close, "expected ',' or ')' in the pen's options");
HLR_HINT(pen_options_close, "options are 'name: value' pairs separated by ',', as in 'pen 2 (colour: \"red\", width: 0.35)'");
HLR_ERROR(plotter_name, "expected a name after 'plotter', as in 'plotter mine { base: \"hp7475a\", pens: 6 }'");
HLR_ERROR(plotter_open, "expected '{' after the plotter's name, as in 'plotter mine { base: \"hp7475a\", pens: 6 }'");
HLR_ERROR(plotter_value, "expected a value after the key and ':', as in 'pens: 6'");
HLR_ERROR(plotter_next_entry, "expected 'key: value' after ',' in the plotter, as in 'pens: 6'");
HLR_HINT(plotter_next_entry, "a trailing ',' is not allowed");
HLR_ERROR(plotter_close, "expected 'key: value' or '}' in the plotter");
HLR_HINT(plotter_close, "entries are 'key: value', separated by ',' or new lines, as in 'plotter mine { base: \"hp7475a\", pens: 6 }'");
HLR_ERROR(label_text, "expected the text after 'label', as in 'label \"bridge\" at (0, 0, 2)'");
HLR_ERROR(label_at, "expected 'at' and where the label goes, as in 'label \"bridge\" at (0, 0, 2)'");
HLR_ERROR(label_point, "expected a point after 'at', as in 'label \"bridge\" at (0, 0, 2)' or 'at page (20, 15)'");
HLR_ERROR(label_size_value, "expected the letters' height in millimetres after 'size:', as in 'size: 4'");
HLR_ERROR(view_name, "expected a name after 'view', as in 'view front = side at page (80, 60)'");
HLR_ERROR(view_camera, "expected a camera after '=', as in 'view front = side at page (80, 60)'");
HLR_HINT(view_camera, "a camera declared by 'camera NAME = ...', or one made here: lookat(...), ortho(...)");
HLR_ERROR(view_at, "expected 'at page (X, Y)' after the view's camera, as in 'view front = side at page (80, 60)'");
HLR_ERROR(view_page, "expected 'page' after 'at': a view goes at a page point, as in 'at page (80, 60)'");
HLR_ERROR(view_point, "expected the page point after 'at page', millimetres from the top-left corner, as in '(80, 60)'");
HLR_ERROR(view_option_value, "expected a value after the option's name and ':', as in 'scale: 0.5'");
HLR_ERROR(views_object, "expected the part after 'views of', as in 'views of bracket'");
HLR_ERROR(dimension_angle_at, "expected 'at' and the angle's vertex after 'angle', as in 'dimension angle at (0, 0, 0) from (1, 0, 0) to (0, 1, 0) in front'");
HLR_ERROR(dimension_vertex, "expected the angle's vertex, a world point, after 'at', as in 'dimension angle at (0, 0, 0) from (1, 0, 0) to (0, 1, 0) in front'");
HLR_ERROR(dimension_from, "expected 'from' (or 'angle at V from') after 'dimension', as in 'dimension from (0, 0, 0) to (80, 0, 0) in front'");
HLR_ERROR(dimension_start, "expected the first world point after 'from', as in 'dimension from (0, 0, 0) to (80, 0, 0) in front'");
HLR_ERROR(dimension_to, "expected 'to' and the second point, as in 'dimension from (0, 0, 0) to (80, 0, 0) in front'");
HLR_ERROR(dimension_end, "expected the second world point after 'to', as in 'dimension from (0, 0, 0) to (80, 0, 0) in front'");
HLR_ERROR(dimension_view, "expected the name of a view after 'in', as in 'in front'");
HLR_ERROR(include_path, "expected a quoted file name after 'include', as in 'include \"parts.hls\"'");
HLR_ERROR(top_statement, "expected a statement");
HLR_HINT(top_statement, "statements start with solid, let, def, for, if, draw, camera, animate, output, paper, style, pen, plotter, label, view, views of, dimension or include");

// clang-format on

#undef HLR_ERROR
#undef HLR_HINT

// clang-format off

// The opening bracket a closing rule matches; 0 for rules that close nothing.
template <typename Rule>
inline constexpr char closes = 0;
template <> inline constexpr char closes<group_close> = '(';
template <> inline constexpr char closes<vector_close> = '(';
template <> inline constexpr char closes<vector_end> = '(';
template <> inline constexpr char closes<call_close> = '(';
template <> inline constexpr char closes<params_close> = '(';
template <> inline constexpr char closes<solid_options_close> = '(';
template <> inline constexpr char closes<paper_options_close> = '(';
template <> inline constexpr char closes<pen_options_close> = '(';
template <> inline constexpr char closes<list_close> = '[';
template <> inline constexpr char closes<comp_close> = '[';
template <> inline constexpr char closes<index_close> = '[';
template <> inline constexpr char closes<interp_close> = '{';
template <> inline constexpr char closes<solid_close> = '{';
template <> inline constexpr char closes<block_close> = '{';
template <> inline constexpr char closes<plotter_close> = '{';

// Opening brackets: each is matched by exactly one closing rule above, and everything between is
// committed, so the control keeps a simple stack of where they opened.
template <typename Rule>
inline constexpr bool opens = false;
template <> inline constexpr bool opens<paren_open> = true;
template <> inline constexpr bool opens<call_open> = true;
template <> inline constexpr bool opens<params_open> = true;
template <> inline constexpr bool opens<solid_options_open> = true;
template <> inline constexpr bool opens<paper_options_open> = true;
template <> inline constexpr bool opens<pen_options_open> = true;
template <> inline constexpr bool opens<plotter_open> = true;
template <> inline constexpr bool opens<list_open> = true;
template <> inline constexpr bool opens<index_open> = true;
template <> inline constexpr bool opens<interp_open> = true;
template <> inline constexpr bool opens<solid_open> = true;
template <> inline constexpr bool opens<block_open> = true;

// Recursion that no bracket marks: prefix operators and `else if` chains.
template <typename Rule>
inline constexpr bool nests = false;
template <> inline constexpr bool nests<neg_operand> = true;
template <> inline constexpr bool nests<not_operand> = true;
template <> inline constexpr bool nests<else_body> = true;

// Rules that expect a name: a reserved word there is reported as such.
template <typename Rule>
inline constexpr bool expects_name = false;
template <> inline constexpr bool expects_name<solid_name> = true;
template <> inline constexpr bool expects_name<let_name> = true;
template <> inline constexpr bool expects_name<def_name> = true;
template <> inline constexpr bool expects_name<next_param> = true;
template <> inline constexpr bool expects_name<params_close> = true;
template <> inline constexpr bool expects_name<for_variable> = true;
template <> inline constexpr bool expects_name<comp_variable> = true;
template <> inline constexpr bool expects_name<camera_name> = true;
template <> inline constexpr bool expects_name<member_name> = true;
template <> inline constexpr bool expects_name<plotter_name> = true;
template <> inline constexpr bool expects_name<output_plotter_name> = true;

// clang-format on

}  // namespace hlr::lang::grammar
