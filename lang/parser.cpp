// parse(): statement by statement over the file, turning syntax errors into diagnostics and
// resynchronising after each one (see parser.hpp). The grammar and the AST actions live in
// grammar.hpp and ast_builder.cpp; this file only knows about text, positions and recovery.
#include "lang/parser.hpp"

#include <algorithm>
#include <array>
#include <cctype>

#include "lang/ast_builder.hpp"

namespace hlr::lang {
namespace {

// ---- a little lexical knowledge: padding, words, tokens -----------------------------------------

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }
bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::size_t skip_padding(std::string_view text, std::size_t pos) {
  while (pos < text.size()) {
    if (is_blank(text[pos])) {
      ++pos;
    } else if (text[pos] == '#') {
      while (pos < text.size() && text[pos] != '\n') ++pos;
    } else {
      break;
    }
  }
  return pos;
}

// Skips a string literal starting at `pos` (a '"'); stops after the closing quote or at the line end.
std::size_t skip_string(std::string_view text, std::size_t pos) {
  for (++pos; pos < text.size() && text[pos] != '\n'; ++pos) {
    if (text[pos] == '\\') {
      ++pos;
    } else if (text[pos] == '"') {
      return pos + 1;
    }
  }
  return std::min(pos, text.size());
}

// End of the last token that ends at or before `to`, scanning from `from`; `from` if there is none.
std::size_t last_token_end(std::string_view text, std::size_t from, std::size_t to) {
  std::size_t end = from;
  std::size_t pos = from;
  while (pos < to) {
    const std::size_t next = skip_padding(text, pos);
    if (next >= to) break;
    pos = text[next] == '"' ? std::min(skip_string(text, next), to) : next + 1;
    end = pos;
  }
  return end;
}

std::string_view word_at(std::string_view text, std::size_t pos) {
  std::size_t end = pos;
  while (end < text.size() && is_word_char(text[end])) ++end;
  return text.substr(pos, end - pos);
}

// Length in bytes of the token at `pos`: a word or number, else one (UTF-8) character.
std::size_t token_length(std::string_view text, std::size_t pos) {
  if (pos >= text.size()) return 0;
  if (is_word_char(text[pos])) return word_at(text, pos).size();
  std::size_t end = pos + 1;
  while (end < text.size() && is_continuation_byte(text[end])) ++end;
  return end - pos;
}

// Statement keywords, the contextual `pen` and `plotter` included: recovery resumes at them.
constexpr std::array kStatementWords = {"solid", "let",     "def",     "for",    "if",
                                        "draw",  "camera",  "animate", "output", "paper",
                                        "style", "include", "return",  "pen",    "plotter"};
constexpr std::array kReservedWords = {
    "solid",   "let",    "def",   "return", "for",     "in",   "if",  "else", "draw", "at",   "camera",
    "animate", "output", "paper", "style",  "include", "then", "and", "or",   "not",  "true", "false"};

template <std::size_t N>
bool one_of(std::string_view word, const std::array<const char*, N>& words) {
  for (const char* w : words) {
    if (word == w) return true;
  }
  return false;
}

bool word_starts_at(std::string_view text, std::size_t pos) {
  return pos == 0 || !is_word_char(text[pos - 1]);
}

// Characters that can start or continue some token of the language.
bool is_known_char(char c) {
  static constexpr std::string_view kPunctuation = "()[]{},.:=+-*/%<>!\"#";
  return is_word_char(c) || is_blank(c) || kPunctuation.find(c) != std::string_view::npos;
}

// ---- recovery -----------------------------------------------------------------------------------

// Is `pos` the first token of its line, or right after a '}'?
bool starts_statement_here(std::string_view text, std::size_t stmt_begin, std::size_t pos) {
  std::size_t i = pos;
  while (i > 0 && (text[i - 1] == ' ' || text[i - 1] == '\t' || text[i - 1] == '\r')) --i;
  if (i == 0 || text[i - 1] == '\n') return true;
  return last_token_end(text, stmt_begin, pos) > stmt_begin &&
         text[last_token_end(text, stmt_begin, pos) - 1] == '}';
}

// Where to resume after an error at `error_pos` in the statement starting at `stmt_begin`: the next
// statement keyword that starts a line, outside the braces that were open at the error; after
// something that starts no statement at all, the next line.
std::size_t resynchronise(std::string_view text, std::size_t stmt_begin, std::size_t error_pos,
                          bool missing_brace, bool statement_expected) {
  if (statement_expected) {  // garbage between statements: try again at the next line
    std::size_t pos = error_pos;
    while (pos < text.size() && text[pos] != '\n') pos = text[pos] == '"' ? skip_string(text, pos) : pos + 1;
    return pos;
  }
  if (missing_brace && error_pos > stmt_begin && error_pos < text.size() && word_starts_at(text, error_pos) &&
      one_of(word_at(text, error_pos), kStatementWords) &&
      starts_statement_here(text, stmt_begin, error_pos)) {
    return error_pos;  // the '}' is missing and the next statement follows: go on from there
  }
  int depth = 0;
  char last = 0;  // the last character of the last token stepped over
  std::size_t pos = stmt_begin;
  auto step = [&](std::size_t p) {  // advances over one token or padding run, counting braces
    if (text[p] == '#' || is_blank(text[p])) return skip_padding(text, p);
    last = text[p];
    if (text[p] == '"') return skip_string(text, p);
    if (text[p] == '{') ++depth;
    if (text[p] == '}' && depth > 0) --depth;
    return is_word_char(text[p]) ? p + word_at(text, p).size() : p + 1;
  };
  auto at_line_start = [&](std::size_t p) {
    while (p > 0 && (text[p - 1] == ' ' || text[p - 1] == '\t' || text[p - 1] == '\r')) --p;
    return p == 0 || text[p - 1] == '\n';
  };
  while (pos < error_pos && pos < text.size()) pos = step(pos);
  if (pos <= stmt_begin) pos = step(stmt_begin);  // always make progress
  while (pos < text.size()) {
    if (depth == 0 && is_word_char(text[pos]) && word_starts_at(text, pos) &&
        one_of(word_at(text, pos), kStatementWords) && (last == '}' || at_line_start(pos))) {
      return pos;
    }
    pos = step(pos);
  }
  return text.size();
}

// ---- syntax errors to diagnostics ---------------------------------------------------------------

std::string describe_char(std::string_view text, std::size_t pos) {
  const auto byte = static_cast<unsigned char>(text[pos]);
  if (byte >= 0x80 || byte < 0x20 || byte == 0x7F) {
    const std::size_t n = token_length(text, pos);
    if (byte >= 0xC2 && byte <= 0xF4 && n > 1) return "'" + std::string(text.substr(pos, n)) + "'";
    static constexpr char kHex[] = "0123456789ABCDEF";
    return std::string("byte 0x") + kHex[byte >> 4U] + kHex[byte & 0xFU];
  }
  return "'" + std::string(1, text[pos]) + "'";
}

Diagnostic to_diagnostic(const detail::SyntaxError& error, const SourceFile& file, std::size_t stmt_begin) {
  const std::string_view text = file.text();
  const auto raw =
      std::clamp<std::size_t>(static_cast<std::size_t>(error.at - text.data()), stmt_begin, text.size());
  const std::size_t found = skip_padding(text, raw);  // the token the grammar stumbled on
  const std::size_t previous_end = last_token_end(text, stmt_begin, found);

  Diagnostic d;
  d.message = error.message;
  d.hint = error.hint ? error.hint : "";
  auto at_found = [&] { d.span = file.span(found, found + token_length(text, found)); };
  auto after_previous = [&] { d.span = file.span(previous_end, previous_end); };

  if (found < text.size() && !is_known_char(text[found])) {
    d.hint = d.message + (d.hint.empty() ? "" : "; " + d.hint);
    d.message = "unexpected character " + describe_char(text, found);
    if (text[found] == ';') d.hint = "statements need no ';' between them: start the next one on a new line";
    if (text[found] == '\'') d.hint = "strings are written in double quotes: \"text\"";
    at_found();
    return d;
  }
  const std::string_view word = word_starts_at(text, found) ? word_at(text, found) : std::string_view();
  // A missing piece at the end of a line is reported where it is missing, not on the next line.
  const bool next_line = found >= text.size() || file.position(found).line > file.position(previous_end).line;
  if (error.expects_name && !next_line && one_of(word, kReservedWords)) {
    d.hint = d.message;
    d.message = "'" + std::string(word) + "' is a reserved word and cannot be used as a name";
    at_found();
    return d;
  }
  if (error.statement_expected) {
    at_found();
    if (found < text.size() && text[found] == '}') {
      d.message = "unexpected '}' with no '{' open";
      d.hint = "remove it, or look for a '{' missing before it";
    } else if (word == "else") {
      d.message = "'else' without an 'if' before it";
      d.hint = "write 'if condition { ... } else { ... }'";
    } else if (word == "vertex" || word == "face" || word == "hole" || word == "line") {
      d.message = "'" + std::string(word) + "' belongs inside a solid";
      d.hint = "write 'solid name { vertex 1 = (0, 0, 0) ... face 1 2 3 }'";
    } else if (!word.empty() && !std::isdigit(static_cast<unsigned char>(word[0]))) {
      d.message = "expected a statement, found '" + std::string(word) + "'";
      const std::size_t after = skip_padding(text, found + word.size());
      if (after < text.size() && text[after] == '=' && text.substr(after, 2) != "==") {
        d.hint = "to bind a name, write 'let " + std::string(word) + " = ...'";
      }
    }
    return d;
  }
  if (next_line && previous_end > stmt_begin) {
    after_previous();
  } else {
    at_found();
  }
  // `f(sides=12)`, `paper A4 (margin=10)`: a name then '=' where an argument list goes on — Python's and
  // OpenSCAD's way of naming an argument.
  if (error.opened_at && error.opener == '(' && !next_line && found < text.size() && text[found] == '=' &&
      text.substr(found, 2) != "==") {
    std::size_t name_end = found;
    while (name_end > stmt_begin && (text[name_end - 1] == ' ' || text[name_end - 1] == '\t')) --name_end;
    std::size_t name_begin = name_end;
    while (name_begin > stmt_begin &&
           (std::isalnum(static_cast<unsigned char>(text[name_begin - 1])) || text[name_begin - 1] == '_'))
      --name_begin;
    if (name_begin < name_end && !std::isdigit(static_cast<unsigned char>(text[name_begin]))) {
      const std::string name(text.substr(name_begin, name_end - name_begin));
      // The value as written, up to the next ',' or ')' outside brackets, for the hint.
      std::size_t v = skip_padding(text, found + 1), end = v;
      for (int depth = 0; end < text.size() && text[end] != '\n' && end - v < 40; ++end) {
        const char c = text[end];
        if (depth == 0 && (c == ',' || c == ')')) break;
        depth += c == '(' || c == '[' ? 1 : c == ')' || c == ']' ? -1 : 0;
      }
      while (end > v && (text[end - 1] == ' ' || text[end - 1] == '\t')) --end;
      const std::string value = end > v ? std::string(text.substr(v, end - v)) : "...";
      d.message = "a named argument takes ':', not '='";
      d.hint = "write '" + name + ": " + value + "' ('==' compares)";
      return d;
    }
  }
  if (error.opened_at) {
    const auto open = static_cast<std::size_t>(error.opened_at - text.data());
    const SourcePos where = file.position(open);
    d.message +=
        " (to close '" + std::string(1, error.opener) + "' at line " + std::to_string(where.line) + ")";
    d.notes.push_back({file.span(open, open + 1), "'" + std::string(1, error.opener) + "' opened here"});
  }
  return d;
}

}  // namespace

ParseResult parse(std::string_view source, std::string file_name, FileId file_id,
                  const ParseOptions& options) {
  return parse(std::make_shared<const SourceFile>(file_id, std::move(file_name), std::string(source)),
               options);
}

ParseResult parse(std::shared_ptr<const SourceFile> file, const ParseOptions& options) {
  ParseResult result;
  result.source = file;
  const std::string_view text = file->text();

  if (text.size() > options.max_bytes) {
    result.diagnostics.push_back(
        {Severity::Error,
         file->span(0, 0),
         "script is too large: " + std::to_string(text.size()) + " bytes, and a script holds at most " +
             std::to_string(options.max_bytes) + " bytes",
         "split it into smaller files joined with `include \"FILE\"`, or import the mesh from an OFF, OBJ or "
         "STL file with `import(\"FILE\")`",
         {}});
    return result;
  }

  Script script;
  script.file = file->id();
  // A statement is 176 bytes and a generated script has 10⁵ of them: growing by doubling moved each one
  // twice and held half again the memory at the last step. Most start a line with their keyword.
  script.statements.reserve(file->lines_starting_with_letter());
  std::size_t pos = skip_padding(text, 0);
  detail::ParseState state;
  state.plain_solid_items = options.plain_solid_items;
  state.plain_expressions = options.plain_expressions;
  while (pos < text.size()) {
    detail::StatementParse parsed = detail::parse_statement(*file, pos, state);
    if (parsed.statement) {
      script.statements.push_back(std::move(*parsed.statement));
      pos = skip_padding(text, parsed.end);
      continue;
    }
    const detail::SyntaxError& error = *parsed.error;
    result.diagnostics.push_back(to_diagnostic(error, *file, pos));
    if (result.diagnostics.size() >= kMaxErrors) {
      result.diagnostics.push_back(
          {Severity::Error,
           result.diagnostics.back().span,
           "too many errors (the limit is " + std::to_string(kMaxErrors) + "); stopping here",
           "fix the first errors and run again",
           {}});
      break;
    }
    const std::size_t error_pos = skip_padding(
        text, std::clamp<std::size_t>(static_cast<std::size_t>(error.at - text.data()), pos, text.size()));
    pos = skip_padding(text,
                       resynchronise(text, pos, error_pos, error.opener == '{', error.statement_expected));
  }
  if (result.diagnostics.size() < kMaxErrors) {
    check_syntax(script, result.diagnostics);
    std::stable_sort(result.diagnostics.begin(), result.diagnostics.end(),
                     [](const Diagnostic& a, const Diagnostic& b) { return a.span.begin < b.span.begin; });
  }
  if (result.diagnostics.empty()) result.script = std::move(script);
  return result;
}

}  // namespace hlr::lang
