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
  // Every rule attempt passes here, millions for a large script, so it costs little: the height of the
  // node stack at the start lives on the C++ stack for the rollback on failure, and only a rule with an
  // action (whose children the action must find) records a mark.
  template <tao::pegtl::apply_mode A, tao::pegtl::rewind_mode M, template <typename...> class Action,
            template <typename...> class Control, typename Input>
  [[nodiscard]] static bool match(Input& in, ParseState& s) {
    constexpr bool has_action =
        A == tao::pegtl::apply_mode::action && !std::is_base_of_v<tao::pegtl::nothing<Rule>, Action<Rule>>;
    const std::size_t height = s.items.size();
    const char* at = in.current();
    if constexpr (grammar::nests<Rule>) {
      if (++s.prefix_depth + s.openers.size() > kMaxNesting) throw SyntaxError{at, kTooDeep};
    }
    if constexpr (has_action) s.marks.push(height);
    const bool matched = tao::pegtl::normal<Rule>::template match<A, M, Action, Control>(in, s);
    if constexpr (has_action) s.marks.pop();
    if constexpr (grammar::nests<Rule>) --s.prefix_depth;
    if (!matched) {
      if (s.items.size() > height)
        s.items.erase(s.items.begin() + static_cast<std::ptrdiff_t>(height), s.items.end());
      s.last_failed_at = at;
      return false;
    }
    if constexpr (grammar::opens<Rule>) {
      s.openers.push_back(at);
      if (s.prefix_depth + s.openers.size() > kMaxNesting) throw SyntaxError{at, kTooDeep};
    }
    if constexpr (grammar::closes<Rule> != 0) {
      if (!s.openers.empty()) s.openers.pop_back();
    }
    return true;
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
