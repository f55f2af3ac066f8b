// Internal to lang/: the PEGTL control class. It keeps the node stack consistent on backtracking,
// tracks open brackets and nesting depth, and turns a failed must<> into a SyntaxError carrying the
// rule's message from grammar_errors.hpp — a rule without a message does not compile.
#pragma once

#include <type_traits>

#include "lang/grammar.hpp"
#include "lang/grammar_errors.hpp"
#include "lang/parse_state.hpp"

namespace hlr::lang::detail {

inline constexpr const char* kTooDeep =
    "too many nested brackets, blocks or prefix operators (the limit is 64)";

template <typename Rule>
struct control : tao::pegtl::normal<Rule> {
  template <typename Input>
  static void start(const Input& in, ParseState& s) {
    s.marks.push_back({s.items.size(), in.current()});
    if constexpr (grammar::nests<Rule>) {
      if (++s.prefix_depth + s.openers.size() > kMaxNesting) throw SyntaxError{in.current(), kTooDeep};
    }
  }

  template <typename Input>
  static void success(const Input& /*in*/, ParseState& s) {
    const ParseState::Mark mark = s.marks.back();
    s.marks.pop_back();
    if constexpr (grammar::nests<Rule>) --s.prefix_depth;
    if constexpr (grammar::opens<Rule>) {
      s.openers.push_back(mark.at);
      if (s.prefix_depth + s.openers.size() > kMaxNesting) throw SyntaxError{mark.at, kTooDeep};
    }
    if constexpr (grammar::closes<Rule> != 0) {
      if (!s.openers.empty()) s.openers.pop_back();
    }
  }

  template <typename Input>
  static void failure(const Input& /*in*/, ParseState& s) {
    const ParseState::Mark mark = s.marks.back();
    s.marks.pop_back();
    if constexpr (grammar::nests<Rule>) --s.prefix_depth;
    s.items.erase(s.items.begin() + static_cast<std::ptrdiff_t>(mark.items), s.items.end());
    s.last_failed_at = mark.at;
  }

  template <typename Input>
  [[noreturn]] static void raise(const Input& in, ParseState& s) {
    static_assert(grammar::error_message<Rule> != nullptr, "every rule under must<> needs an error_message");
    SyntaxError error;
    error.at = s.last_failed_at ? s.last_failed_at : in.current();
    error.message = grammar::error_message<Rule>;
    error.hint = grammar::error_hint<Rule>;
    if constexpr (grammar::closes<Rule> != 0) {
      if (!s.openers.empty()) error.opened_at = s.openers.back();
      error.opener = grammar::closes<Rule>;
    }
    error.expects_name = grammar::expects_name<Rule>;
    error.statement_expected = std::is_same_v<Rule, grammar::top_statement>;
    throw error;
  }
};

}  // namespace hlr::lang::detail
