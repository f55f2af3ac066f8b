// Easing curves for keyframe tracks: maps of [0, 1] onto itself with ease(0) = 0 and ease(1) = 1 (step
// jumps at 1; back overshoots in between), as animation tools name them (Penner's set).
#pragma once

#include <optional>
#include <string_view>
#include <vector>

namespace hlr {

enum class Easing {
  Linear,
  Step,  // holds the start value until the next key
  Smoothstep,
  Smootherstep,
  InSine,
  OutSine,
  InOutSine,
  InQuad,
  OutQuad,
  InOutQuad,
  InCubic,
  OutCubic,
  InOutCubic,
  InQuart,
  OutQuart,
  InOutQuart,
  InExpo,
  OutExpo,
  InOutExpo,
  InBack,
  OutBack,
  InOutBack,
};

// "linear", "in_out_cubic", ...; nullopt for an unknown name.
std::optional<Easing> easing_named(std::string_view name);
// Every name, in the order of the enum (for messages and the docs).
const std::vector<std::string_view>& easing_names();

// The curve at x, x clamped to [0, 1].
double ease(Easing easing, double x);

}  // namespace hlr
