// What runtime/repl/repl_session.cpp and runtime/repl/repl_commands.cpp share: a rendered view, replies, and
// the box round what is drawn (the pivot of :orbit, the bounds a value shows).
#pragma once

#include <algorithm>
#include <string>

#include "core/hlr/render_frame.hpp"
#include "core/solid/solid.hpp"
#include "runtime/eval/frame_scene.hpp"
#include "runtime/repl/repl_session.hpp"
#include "runtime/values/format_value.hpp"

namespace hlr::runtime {

// A rendered frame of the session.
struct ReplSession::View {
  FrameScene scene;
  std::string camera;
  Camera view_camera;
  FrameResult result;
  double render_ms = 0;
};

namespace repl {

inline ReplReply done(std::string text) { return {ReplReply::Kind::Done, std::move(text)}; }
inline ReplReply error(std::string text) {
  if (!text.empty() && text.back() != '\n') text += '\n';
  return {ReplReply::Kind::Error, std::move(text)};
}

inline std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

inline std::string point_text(Point3 p) {
  return "(" + format_number(p.x) + ", " + format_number(p.y) + ", " + format_number(p.z) + ")";
}

// The box round solids' vertices.
struct Extent {
  Point3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  void add(const Solid& s) {
    for (const Point3& p : s.vertices) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  }
  bool empty() const { return lo.x > hi.x; }
  Point3 middle() const { return {(lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2}; }
};

}  // namespace repl
}  // namespace hlr::runtime
