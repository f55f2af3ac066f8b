// `view NAME = CAMERA at page (X, Y) [scale: S] [label: TEXT] [hidden: BOOL]`: a camera's drawing placed on
// the sheet. The pipeline lays the views out and draws them (runtime/pipeline/sheet_render.hpp); here they
// are only checked and recorded.
#include <cctype>
#include <cmath>

#include "core/camera/ortho_camera.hpp"
#include "core/geometry/box3.hpp"
#include "core/limits.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/eval/option_list.hpp"

namespace hlr::runtime {

namespace {

const OptionList& view_options() {
  static const OptionList list{
      "",
      "option",
      "scale: 0.5",
      "a view's options are scale: millimetres per drawing unit above 0 (else the paper's scale:, else "
      "one scale fitted to the sheet), label: the text under it (\"\" for none; else its name in capitals) "
      "hidden: true or false (its hidden lines drawn or not, whatever the style) and show: the solids it "
      "draws instead of the script's (a section, say)",
      {{"scale", ValueKind::Number},
       {"label", ValueKind::String},
       {"hidden", ValueKind::Bool},
       {"show", ValueKind::Solid, {}, true}}};
  return list;
}

const OptionList& dimension_options() {
  static const OptionList list{
      "dimension: ",
      "option",
      "offset: 12",
      "a dimension's options are offset: millimetres from the points to the dimension line (default 10; "
      "negative: below, or right of an upright one), direction: \"aligned\" (the true distance, the "
      "default), \"horizontal\" or \"vertical\" (along the view's right or up), radius: an angle's arc "
      "in millimetres (default 15), extend: \"from\", \"to\" or \"both\" (the legs that are no edge of the "
      "part, drawn from the vertex), text: written instead of the value, precision: decimals at most (0 to "
      "6, default 2), unit: \"mm\" (the default), \"cm\", \"m\" or \"in\" (a world unit read as a "
      "millimetre) and pen: its pen (default 1)",
      {{"offset", ValueKind::Number},
       {"direction", ValueKind::String},
       {"radius", ValueKind::Number},
       {"extend", ValueKind::String},
       {"text", ValueKind::String},
       {"precision", ValueKind::Number},
       {"unit", ValueKind::String},
       {"pen", ValueKind::Number}}};
  return list;
}

const OptionList& views_options() {
  static const OptionList list{
      "views of: ",
      "option",
      "projection: \"first\"",
      "the standard views' options are projection: \"third\" (the default: the top view above the front, "
      "the right side to its right) or \"first\" (the top view below, the left side to the right), iso: "
      "true or false (an isometric view beside them, the default true), scale: millimetres per unit (else "
      "the paper's, else fitted to the sheet), gap: millimetres between the views (default 20) and hidden: "
      "true or false (the orthographic views' hidden lines, whatever the style)",
      {{"projection", ValueKind::String},
       {"iso", ValueKind::Bool},
       {"scale", ValueKind::Number},
       {"gap", ValueKind::Number},
       {"hidden", ValueKind::Bool}}};
  return list;
}

std::string capitals(const std::string& name) {
  std::string out = name;
  for (char& c : out) c = c == '_' ? ' ' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

void Evaluator::check_new_view(const std::string& name, const lang::SourceSpan& span) const {
  for (const ViewSetting& v : out_.views)
    if (v.camera.name == name) {
      lang::Diagnostic d;
      d.span = span;
      d.message = "view '" + name + "' is already declared";
      d.hint = "give each view its own name";
      d.notes.push_back({v.name_span, "the first view '" + v.camera.name + "' is here"});
      throw EvalError(std::move(d));
    }
}

void Evaluator::exec_views(const lang::ViewsStmt& views, const lang::Stmt& stmt, const ScopePtr& scope) {
  // The part's bounding box: the views look at its centre from outside it.
  const Value part = eval(*views.object, scope);
  if (!part.is(ValueKind::Solid) && !part.is(ValueKind::Group) && !part.is(ValueKind::List))
    fail(views.object->span,
         "'views of' needs a solid, a group or a list of them, got " + kind_with_article(part.kind()),
         "for example: views of bracket");
  Scene solids;
  std::vector<int> pens;
  add_to_scene(part, Affine3{}, views.object->span, views.object->span, 1, solids, pens);
  Box3 bounds;
  for (const SceneObject& o : solids.objects)
    for (const Point3& p : o.solid->vertices) bounds.include(p);
  if (!(bounds.lo.x <= bounds.hi.x) || !(length(bounds.hi - bounds.lo) > 0))
    fail(views.object->span, "the part has no size to look at", "give 'views of' a solid with faces");

  const OptionList& list = views_options();
  const GivenOptions given =
      check_options(views.options, list, [&](const lang::Expr& e) { return eval(e, scope); });
  bool third = true;
  if (const GivenOption* o = find(given, "projection")) {
    const std::string& word = o->value.as_string();
    if (word != "first" && word != "third")
      fail(o->span, list.who + "option 'projection' must be \"first\" or \"third\", got \"" + word + "\"",
           list.hint);
    third = word == "third";
  }
  const GivenOption* iso_option = find(given, "iso");
  const bool iso = iso_option ? iso_option->value.as_bool() : true;
  ViewGridCell cell;
  if (const GivenOption* o = find(given, "gap"))
    cell.gap_mm = number_in(
        *o, list, [](double x) { return x >= 0 && x <= kMaxPaperSideMm; },
        "from 0 to " + format_for_message(kMaxPaperSideMm) + " millimetres");
  std::optional<double> scale;
  if (const GivenOption* o = find(given, "scale"))
    scale = number_in(
        *o, list, [](double x) { return x > 0 && x <= kMaxPaperSideMm; },
        "above 0 millimetres per unit, at most " + format_for_message(kMaxPaperSideMm));
  std::optional<bool> hidden;
  if (const GivenOption* o = find(given, "hidden")) hidden = o->value.as_bool();

  // Third angle: the top view above the front, the right side to its right, the isometric view top right.
  // First angle: the top view below the front, the left side to its right, the isometric view bottom right.
  const Point3 centre = lerp(bounds.lo, bounds.hi, 0.5);
  const double away = 2 * length(bounds.hi - bounds.lo) + 1;
  struct Standard {
    const char* name;
    Vector3 from;  // the eye's direction from the centre
    Vector3 up;
    int column, row;
  };
  std::vector<Standard> standard;
  if (third)
    standard = {{"front", {0, -1, 0}, {0, 0, 1}, 0, 1},
                {"top", {0, 0, 1}, {0, 1, 0}, 0, 0},
                {"right", {1, 0, 0}, {0, 0, 1}, 1, 1}};
  else
    standard = {{"front", {0, -1, 0}, {0, 0, 1}, 0, 0},
                {"top", {0, 0, 1}, {0, 1, 0}, 0, 1},
                {"left", {-1, 0, 0}, {0, 0, 1}, 1, 0}};
  if (iso) standard.push_back({"iso", {1, -1, 1}, {0, 0, 1}, 1, third ? 0 : 1});
  for (const Standard& s : standard) {
    check_new_view(s.name, stmt.span);
    ViewSetting setting;
    setting.camera.name = s.name;
    setting.camera.span = stmt.span;
    setting.name_span = stmt.span;
    OrthoParameters o;
    o.eye = centre + (away / length(s.from)) * s.from;
    o.target = centre;
    o.up = s.up;
    // The sheet's scale sets a view's size on the sheet; the height frames the part when one view is drawn
    // alone (--camera front).
    o.height = 1.2 * length(bounds.hi - bounds.lo);
    setting.camera.camera = ortho_camera(o);
    setting.grid = cell;
    setting.grid->column = s.column;
    setting.grid->row = s.row;
    setting.mm_per_unit = scale;
    setting.label = capitals(s.name);
    // The isometric view shows the part's shape: without hidden lines unless asked.
    setting.hidden = std::string(s.name) == "iso" ? std::optional<bool>(hidden.value_or(false)) : hidden;
    out_.views.push_back(std::move(setting));
  }
}

void Evaluator::exec_view(const lang::ViewStmt& view, const lang::Stmt& stmt, const ScopePtr& scope) {
  check_new_view(view.name.text, view.name.span);
  ViewSetting setting;
  setting.camera.name = view.name.text;
  setting.camera.span = stmt.span;
  setting.name_span = view.name.span;

  // A camera value, or the name of a camera declared before (when the name is bound to no camera).
  const Camera* declared = nullptr;
  if (const auto* ref = std::get_if<lang::NameRef>(&view.camera->node)) {
    const Binding* bound = scope->find(ref->name);
    if (!bound || !bound->value.is(ValueKind::Camera))
      for (const NamedCamera& c : out_.cameras)
        if (c.name == ref->name) declared = &c.camera;
  }
  if (declared) {
    setting.camera.camera = *declared;
  } else {
    const Value camera = eval(*view.camera, scope);
    if (!camera.is(ValueKind::Camera))
      fail(view.camera->span, "a view needs a camera, got " + kind_with_article(camera.kind()),
           "a camera declared by 'camera NAME = ...', or one made here, as in 'view " + view.name.text +
               " = ortho(eye: (0, -10, 0), target: (0, 0, 0), height: 4) at page (80, 60)'");
    setting.camera.camera = camera.as_camera();
  }

  const Value at = eval(*view.point, scope);
  if (!at.is(ValueKind::Vector))
    fail(view.point->span, "a view goes at a page point, got " + kind_with_article(at.kind()),
         "'at page (80, 60)': millimetres from the page's top-left corner");
  const Vector3 p = at.as_vector();
  if (!(std::isfinite(p.x) && std::isfinite(p.y)) || p.x < 0 || p.y < 0 || p.z != 0 ||
      p.x > kMaxPaperSideMm || p.y > kMaxPaperSideMm)
    fail(view.point->span,
         "a page point is (x, y) in millimetres from the page's top-left corner, both 0 or more",
         "for example: at page (80, 60)");
  setting.at_mm = {p.x, p.y};

  OptionList list = view_options();
  list.who = "view '" + view.name.text + "': ";
  const GivenOptions given =
      check_options(view.options, list, [&](const lang::Expr& e) { return eval(e, scope); });
  if (const GivenOption* o = find(given, "scale"))
    setting.mm_per_unit = number_in(
        *o, list, [](double x) { return x > 0 && x <= kMaxPaperSideMm; },
        "above 0 millimetres per unit, at most " + format_for_message(kMaxPaperSideMm));
  setting.label = capitals(view.name.text);
  if (const GivenOption* o = find(given, "label")) setting.label = o->value.as_string();
  if (const GivenOption* o = find(given, "hidden")) setting.hidden = o->value.as_bool();
  if (const GivenOption* o = find(given, "show")) {
    setting.shows.emplace();
    add_to_scene(o->value, Affine3{}, o->span, o->span, 1, *setting.shows, setting.show_pens);
  }
  out_.views.push_back(std::move(setting));
}

void Evaluator::exec_dimension(const lang::DimensionStmt& dimension, const lang::Stmt& stmt,
                               const ScopePtr& scope) {
  DimensionSetting setting;
  setting.span = stmt.span;
  setting.view_span = dimension.view ? dimension.view->span : stmt.span;
  if (dimension.view) setting.view_name = dimension.view->text;
  const auto point = [&](const lang::Expr& e, const char* which) {
    const Value v = eval(e, scope);
    if (!v.is(ValueKind::Vector))
      fail(e.span,
           std::string("a dimension runs between world points: '") + which + "' needs a point, got " +
               kind_with_article(v.kind()),
           "for example: dimension from (0, 0, 0) to (80, 0, 0) in front");
    const Vector3 p = v.as_vector();
    if (!is_finite(Point3{p.x, p.y, p.z})) fail(e.span, "the point must be finite");
    return Point3{p.x, p.y, p.z};
  };
  PageDimension& d = setting.dimension;
  if (dimension.vertex) d.vertex = point(*dimension.vertex, "at");
  d.from = point(*dimension.from, "from");
  d.to = point(*dimension.to, "to");
  const OptionList& list = dimension_options();
  const GivenOptions given =
      check_options(dimension.options, list, [&](const lang::Expr& e) { return eval(e, scope); });
  // Each option belongs to distances or to angles; the other kind would silently ignore it.
  for (const char* name : {"offset", "direction", "unit"})
    if (const GivenOption* o = find(given, name); o && d.vertex)
      fail(o->span,
           std::string("'") + name +
               ":' is for a distance; an angle takes radius:, extend:, text:, precision: and pen:",
           "write radius: MM for the arc's size");
  for (const char* name : {"radius", "extend"})
    if (const GivenOption* o = find(given, name); o && !d.vertex)
      fail(o->span,
           std::string("'") + name + ":' is for an angle, written 'dimension angle at V from P to Q'",
           "a distance takes offset: MM for where its line goes");
  if (const GivenOption* o = find(given, "extend")) {
    const std::string& word = o->value.as_string();
    if (word != "from" && word != "to" && word != "both")
      fail(o->span, list.who + "option 'extend' must be \"from\", \"to\" or \"both\", got \"" + word + "\"",
           list.hint);
    d.extend_from = word != "to";
    d.extend_to = word != "from";
  }
  if (const GivenOption* o = find(given, "radius"))
    d.radius_mm = number_in(
        *o, list, [](double x) { return x >= 1 && x <= kMaxPaperSideMm; },
        "from 1 to " + format_for_message(kMaxPaperSideMm) + " millimetres");
  if (const GivenOption* o = find(given, "unit")) {
    const std::string& word = o->value.as_string();
    if (const std::optional<DimensionUnit> unit = dimension_unit_named(word))
      d.unit = *unit;
    else
      fail(o->span, list.who + "option 'unit' must be \"mm\", \"cm\", \"m\" or \"in\", got \"" + word + "\"",
           list.hint);
  }
  if (const GivenOption* o = find(given, "offset"))
    d.offset_mm = number_in(
        *o, list, [](double x) { return std::abs(x) <= kMaxPaperSideMm; },
        "at most " + format_for_message(kMaxPaperSideMm) + " millimetres either way");
  if (const GivenOption* o = find(given, "direction")) {
    const std::string& word = o->value.as_string();
    if (word == "aligned")
      d.direction = DimensionDirection::Aligned;
    else if (word == "horizontal")
      d.direction = DimensionDirection::Horizontal;
    else if (word == "vertical")
      d.direction = DimensionDirection::Vertical;
    else
      fail(o->span,
           list.who + "option 'direction' must be \"aligned\", \"horizontal\" or \"vertical\", got \"" +
               word + "\"",
           list.hint);
  }
  if (const GivenOption* o = find(given, "text")) d.text = o->value.as_string();
  if (const GivenOption* o = find(given, "precision"))
    d.precision = static_cast<int>(number_in(
        *o, list, [](double x) { return x >= 0 && x <= 6 && whole(x); }, "a whole number from 0 to 6"));
  if (const GivenOption* o = find(given, "pen"))
    d.pen = static_cast<int>(number_in(
        *o, list, [](double x) { return x >= 1 && x <= kMaxPen && whole(x); },
        "a whole number from 1 to " + std::to_string(kMaxPen)));
  out_.dimensions.push_back(std::move(setting));
}

}  // namespace hlr::runtime
