// Paper sizes and the mapping of a drawing onto a page, shared by every device so that PDF, SVG, JSON
// (and HPGL, after its own flip) put each piece at the same millimetres.
//
// Page coordinates are millimetres from the page's top-left corner with y growing downwards, as PDF and
// SVG draw; picture coordinates grow upwards, so the mapping flips y. The camera frames the picture
// (PageFit::Camera, the default): its own frame (`aspect:`, Desens' window) or, without one, the window
// picture_frame() gives it on this page — its field of view spanning the drawing area's shorter side — is
// fitted into the page minus its margins with one uniform scale and centred, so the scale depends on the
// camera and the paper only, never on what is drawn. PageFit::Drawing fits the bounds of the pieces
// instead (a camera's own frame still wins). With an explicit scale (PageSpec::mm_per_unit) nothing is
// fitted: the frame, or the drawing, is centred at that scale. A caption, when a device prints one, lives
// in the bottom margin and does not move the drawing.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/geometry/rect2.hpp"
#include "core/geometry/vector.hpp"
#include "core/hlr/visible_segment.hpp"
#include "core/limits.hpp"  // kMaxPaperSideMm, the largest sheet side check_page_spec() accepts

namespace hlr {

struct Paper {
  double width_mm = 297;  // A4 landscape
  double height_mm = 210;
};

// Named sizes A0–A6, Letter, Legal, Tabloid, matched case-insensitively ("A4", "a4", "letter").
// Portrait (width < height) unless `landscape`; nullopt for an unknown name.
std::optional<Paper> paper_by_name(std::string_view name, bool landscape = false);
// The accepted names in their canonical spelling, for error messages.
const std::vector<std::string_view>& paper_names();

// A paper_by_name() name or a custom size "WxH" in millimetres ("300x200", "300x200mm", "215.9X279.4MM"):
// plain decimal numbers, no sign, exponent or spaces. Named and custom sizes follow the same rule: the
// sheet is turned so that width ≥ height when `landscape`, width ≤ height otherwise ("300x200" in
// portrait is 200 × 300 mm; a square sheet is unchanged). Only the spelling is checked here: nullopt for
// an unknown name or malformed size; zero or oversized sheets parse and are rejected by check_page_spec().
std::optional<Paper> parse_paper(std::string_view text, bool landscape);

// What sets the page scale and origin: the camera's picture window (the default), or the drawing's bounds.
enum class PageFit { Camera, Drawing };
// "camera" or "drawing" (as scripts and --fit spell them); nullopt for anything else.
std::optional<PageFit> page_fit_by_name(std::string_view name);

struct PageSpec {
  // A constructor rather than an aggregate, so that {paper, margin} leaves the scale unset without
  // -Wmissing-field-initializers.
  constexpr PageSpec(Paper paper_ = {}, double margin_mm_ = 12,
                     std::optional<double> mm_per_unit_ = std::nullopt, PageFit fit_ = PageFit::Camera)
      : paper(paper_), margin_mm(margin_mm_), mm_per_unit(mm_per_unit_), fit(fit_) {}

  Paper paper;
  double margin_mm = 12;  // on all four sides
  // When set, the drawing is not fitted: 1 picture unit is this many millimetres on the page, and the
  // extent is centred on the page (a drawing larger than the room between the margins runs into the
  // margins or off the sheet). Must be finite and positive.
  std::optional<double> mm_per_unit;
  PageFit fit = PageFit::Camera;
};

struct PageLayout {
  double page_width_mm = 297;
  double page_height_mm = 210;
  double scale = 1;       // millimetres per picture unit
  Point2 picture_centre;  // picture point that lands on the page centre

  // Computed about the centre, not from origin(): keeps precision when the picture sits far from (0, 0).
  Point2 to_page_mm(Point2 picture) const {
    return {0.5 * page_width_mm + scale * (picture.x - picture_centre.x),
            0.5 * page_height_mm - scale * (picture.y - picture_centre.y)};
  }
  // Page position (mm, top-left, y down) of the picture point (0, 0): to_page_mm(p) = origin + s·(x, −y).
  Point2 origin() const { return to_page_mm(Point2{0, 0}); }
};

// Throws DeviceError naming the problem when the paper is not finite and positive (or has a side over
// kMaxPaperSideMm), the margins leave no room, or an explicit mm_per_unit is not finite and positive;
// devices call it before creating any file.
void check_page_spec(const PageSpec& spec);

// Fits `extent` into the page. An empty extent (nothing to draw) maps the picture origin to the page
// centre at scale 1; a degenerate one (a point, a line) is fitted along its non-zero side, and a point
// lands at the centre. With spec.mm_per_unit the scale is that value for every extent (empty included)
// and the extent's centre lands on the page centre. Throws as check_page_spec() does.
PageLayout fit_rect_to_page(const Rect2& extent, const PageSpec& spec);

// The picture window of a camera without a frame of its own on this page, centred on the picture origin:
// ±half_extent along the shorter side of the drawing area (the paper minus the margins), its aspect the
// drawing area's; with spec.mm_per_unit, the whole drawing area at that scale. Throws as check_page_spec().
Rect2 camera_window(double half_extent, const PageSpec& spec);

// The frame a camera's picture is clipped to and laid out by on this page: its own (`aspect:`, Desens'
// window), else with PageFit::Camera its camera_window(), else none (the drawing is fitted).
std::optional<Rect2> picture_frame(const Camera& camera, const PageSpec& spec);

// `camera` with its frame set to picture_frame() on this page: what the engine clips to and devices show.
Camera framed_camera(Camera camera, const PageSpec& spec);

// The extent a device fits: `frame` when present, else the bounds of the pieces' picture end points.
Rect2 drawing_extent(const std::optional<Rect2>& frame, const std::vector<VisibleSegment>& segments);

inline PageLayout fit_to_page(const std::optional<Rect2>& frame, const std::vector<VisibleSegment>& segments,
                              const PageSpec& spec) {
  return fit_rect_to_page(drawing_extent(frame, segments), spec);
}

}  // namespace hlr
