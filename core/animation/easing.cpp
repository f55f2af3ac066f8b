#include "core/animation/easing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hlr {

namespace {

// The overshoot of the back curves (about 10 %), and its in-out variant, as the usual tables give them.
constexpr double kBack = 1.70158;
constexpr double kBackInOut = kBack * 1.525;
constexpr double kExpoBase = 2;
constexpr double kExpoRate = 10;  // 2^(10(x − 1)): 1/1024 at the start

double in_power(double x, int n) { return std::pow(x, n); }
double out_power(double x, int n) { return 1 - std::pow(1 - x, n); }
double in_out_power(double x, int n) {
  return x < 0.5 ? std::pow(2, n - 1) * std::pow(x, n) : 1 - std::pow(-2 * x + 2, n) / 2;
}

}  // namespace

const std::vector<std::string_view>& easing_names() {
  static const std::vector<std::string_view> names = {
      "linear",       "step",     "smoothstep", "smootherstep", "in_sine",  "out_sine",
      "in_out_sine",  "in_quad",  "out_quad",   "in_out_quad",  "in_cubic", "out_cubic",
      "in_out_cubic", "in_quart", "out_quart",  "in_out_quart", "in_expo",  "out_expo",
      "in_out_expo",  "in_back",  "out_back",   "in_out_back"};
  return names;
}

std::optional<Easing> easing_named(std::string_view name) {
  const auto& names = easing_names();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) return std::nullopt;
  return static_cast<Easing>(it - names.begin());
}

double ease(Easing easing, double x) {
  x = std::clamp(x, 0.0, 1.0);
  constexpr double pi = std::numbers::pi;
  switch (easing) {
    case Easing::Linear:
      return x;
    case Easing::Step:
      return x < 1 ? 0 : 1;
    case Easing::Smoothstep:
      return x * x * (3 - 2 * x);
    case Easing::Smootherstep:
      return x * x * x * (x * (6 * x - 15) + 10);
    case Easing::InSine:
      return 1 - std::cos(x * pi / 2);
    case Easing::OutSine:
      return std::sin(x * pi / 2);
    case Easing::InOutSine:
      return (1 - std::cos(pi * x)) / 2;
    case Easing::InQuad:
      return in_power(x, 2);
    case Easing::OutQuad:
      return out_power(x, 2);
    case Easing::InOutQuad:
      return in_out_power(x, 2);
    case Easing::InCubic:
      return in_power(x, 3);
    case Easing::OutCubic:
      return out_power(x, 3);
    case Easing::InOutCubic:
      return in_out_power(x, 3);
    case Easing::InQuart:
      return in_power(x, 4);
    case Easing::OutQuart:
      return out_power(x, 4);
    case Easing::InOutQuart:
      return in_out_power(x, 4);
    case Easing::InExpo:
      return x == 0 ? 0 : std::pow(kExpoBase, kExpoRate * (x - 1));
    case Easing::OutExpo:
      return x == 1 ? 1 : 1 - std::pow(kExpoBase, -kExpoRate * x);
    case Easing::InOutExpo:
      if (x == 0 || x == 1) return x;
      return x < 0.5 ? std::pow(kExpoBase, kExpoRate * (2 * x - 1)) / 2
                     : (2 - std::pow(kExpoBase, -kExpoRate * (2 * x - 1))) / 2;
    case Easing::InBack:
      return (kBack + 1) * x * x * x - kBack * x * x;
    case Easing::OutBack:
      return 1 + (kBack + 1) * std::pow(x - 1, 3) + kBack * std::pow(x - 1, 2);
    case Easing::InOutBack:
      return x < 0.5 ? std::pow(2 * x, 2) * ((kBackInOut + 1) * 2 * x - kBackInOut) / 2
                     : (std::pow(2 * x - 2, 2) * ((kBackInOut + 1) * (2 * x - 2) + kBackInOut) + 2) / 2;
  }
  return x;
}

}  // namespace hlr
