// Looking up a device's built-in profiles (HPGL plotters, G-code machines) by name: names match ignoring
// ASCII case, and messages list them in their table's order.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hlr {

inline bool equal_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
  for (std::size_t i = 0; i < a.size(); ++i)
    if (lower(a[i]) != lower(b[i])) return false;
  return true;
}

// The profile named `name` (any case) among `profiles`, each with a `name` member.
template <typename Profile>
std::optional<Profile> profile_by_name(const std::vector<Profile>& profiles, std::string_view name) {
  for (const Profile& p : profiles)
    if (equal_ignoring_case(p.name, name)) return p;
  return std::nullopt;
}

// "a, b, c": the profiles' names for messages.
template <typename Profile>
std::string profile_names(const std::vector<Profile>& profiles) {
  std::string list;
  for (const Profile& p : profiles) list += (list.empty() ? "" : ", ") + p.name;
  return list;
}

}  // namespace hlr
