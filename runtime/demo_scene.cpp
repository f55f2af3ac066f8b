#include "runtime/demo_scene.hpp"

#include <chrono>
#include <cstdio>
#include <string>

#include "core/camera/desens_camera.hpp"
#include "stdlib/desens_models.hpp"

namespace hlr {
namespace {

struct Waypoint {
  Point3 ship;      // OBJECT POSITION
  Point3 observer;  // OBSERVERS POSITION
};

// Carrier (2)–(5) of the thesis: the ship steams −42 ft per view, the aircraft closes on the stern.
constexpr Waypoint kApproach[] = {
    {{126, 0, 0}, {1914, 151, 112.5}},
    {{84, 0, 0}, {1598, 96, 96}},
    {{42, 0, 0}, {1300, 43.5, 80}},
    {{0, 0, 0}, {950, 0, 66}},
};

std::string caption_for(const char* label, const DesensParameters& p) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s   ship (%.1f, %.1f, %.1f)   observer (%.1f, %.1f, %.1f)   heading %.1f/%.1f/%.1f",
                label, p.object_position.x, p.object_position.y, p.object_position.z, p.observer_position.x,
                p.observer_position.y, p.observer_position.z, p.heading.x, p.heading.y, p.heading.z);
  return buf;
}

}  // namespace

std::vector<DrawingPage> render_carrier_demo(int approach_frames, const HlrOptions& options, DemoStats& stats) {
  Scene scene;
  scene.objects.push_back({"carrier", stdlib::desens_carrier()});
  std::vector<DesensParameters> views;
  std::vector<std::string> captions;

  DesensParameters overview;  // Carrier (1): the whole ship from 500 ft
  overview.object_position = {2000, 0, 0};
  overview.attitude = {60, 0, 0};
  overview.observer_position = {0, 0, 500};
  overview.heading = {190, -5, 0};
  views.push_back(overview);
  captions.push_back(caption_for("Carrier (1)", overview));

  const int segments = static_cast<int>(std::size(kApproach)) - 1;
  for (int f = 0; f < approach_frames; ++f) {
    const double u = approach_frames > 1 ? static_cast<double>(f) / (approach_frames - 1) * segments : 0;
    const int k = std::min(static_cast<int>(u), segments - 1);
    const double t = u - k;
    DesensParameters p;
    p.object_position = lerp(kApproach[k].ship, kApproach[k + 1].ship, t);
    p.observer_position = lerp(kApproach[k].observer, kApproach[k + 1].observer, t);
    p.heading = {10, 0, 0};
    views.push_back(p);
    captions.push_back(caption_for(("Approach frame " + std::to_string(f + 1)).c_str(), p));
  }

  std::vector<DrawingPage> pages;
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < views.size(); ++i) {
    const Camera camera = desens_camera(views[i]);
    FrameResult frame = render_frame(scene, camera, options);
    stats.segments += frame.segments.size();
    pages.push_back({std::move(frame.segments), camera.frame, captions[i]});
  }
  stats.frames = pages.size();
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return pages;
}

}  // namespace hlr
