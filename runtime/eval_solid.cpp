// solid NAME (OPTIONS) { vertex ... face ... line ... }: the options become hlr::SolidBuildOptions, the
// items go to hlr::SolidBuilder, each tagged with its index so that every builder diagnostic
// (non-planar face, unknown vertex, ...) points at its item. Errors fail the statement, all of them
// reported together; warnings (a reoriented face) are kept with the frame and printed once.
#include <algorithm>
#include <array>
#include <string_view>

#include "core/format_number.hpp"
#include "core/solid/solid_builder.hpp"
#include "lang/overloaded.hpp"
#include "runtime/eval_detail.hpp"
#include "runtime/evaluator.hpp"
#include "runtime/format_value.hpp"

namespace hlr::runtime {

namespace {

using lang::Overloaded;

// Numbers by value ("01" is vertex 1), names as written.
std::string vertex_key(const lang::VertexId& id) {
  return id.is_number ? std::to_string(id.number) : id.text;
}

std::vector<std::string> vertex_keys(const std::vector<lang::VertexId>& ids) {
  std::vector<std::string> out;
  out.reserve(ids.size());
  for (const lang::VertexId& id : ids) out.push_back(vertex_key(id));
  return out;
}

constexpr std::size_t kFewIds = 16;

// A face whose id list comes back to a vertex it left (not just a vertex repeated in a row) is a loop
// in the theses' style (Desens' LSTFAC): edges walked both ways are bridges or lines on the face.
bool revisits_a_vertex(const std::vector<std::string>& ids) {
  // The walk with repeats in a row collapsed and, when written closed (1 2 3 1), the closing id dropped.
  std::vector<std::string_view> walk;
  walk.reserve(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (i == 0 || ids[i] != ids[i - 1]) walk.push_back(ids[i]);
  if (ids.size() > 1 && ids.front() == ids.back() && walk.size() > 1) walk.pop_back();
  if (walk.size() <= kFewIds) {  // most faces: compare pairs, no sorting
    for (std::size_t i = 0; i < walk.size(); ++i)
      for (std::size_t j = i + 1; j < walk.size(); ++j)
        if (walk[i] == walk[j]) return true;
    return false;
  }
  std::sort(walk.begin(), walk.end());
  return std::adjacent_find(walk.begin(), walk.end()) != walk.end();
}

// ---- options: solid NAME (crease: 30, planarity: 0.003, crossing_holes: true, fix_winding: false) ----

constexpr std::array<std::string_view, 4> kOptionNames = {"crease", "planarity", "crossing_holes",
                                                          "fix_winding"};
constexpr double kMaxPlanarity = 0.05;  // 5% of a face's size off its plane is no longer a plane
constexpr const char* kOptionsHint =
    "the options are crease: degrees from 0 to 180, planarity: a fraction of the face's size above 0 "
    "and at most 0.05, crossing_holes: true or false, fix_winding: true or false";

// The build options a solid statement asks for; `eval` evaluates an option's expression. Every
// mistake is an error at the option, with the list of options as the hint.
template <typename Eval>
SolidBuildOptions build_options(const lang::SolidStmt& solid, Eval&& eval) {
  SolidBuildOptions options;
  const std::string who = "solid '" + solid.name.text + "': ";
  std::vector<std::string_view> seen;
  for (const lang::Argument& option : solid.options) {
    if (!option.label) fail(option.span, who + "an option needs a name, as in 'crease: 30'", kOptionsHint);
    const std::string& name = option.label->text;
    if (std::find(kOptionNames.begin(), kOptionNames.end(), name) == kOptionNames.end()) {
      const std::string guess =
          did_you_mean(name, std::vector<std::string>(kOptionNames.begin(), kOptionNames.end()));
      fail(option.span, who + "unknown option '" + name + "'",
           guess.empty() ? kOptionsHint : guess + " " + kOptionsHint);
    }
    if (std::find(seen.begin(), seen.end(), name) != seen.end())
      fail(option.span, who + "option '" + name + "' is given twice", kOptionsHint);
    seen.push_back(name);

    const Value value = eval(*option.value);
    const bool flag = name == "crossing_holes" || name == "fix_winding";
    const ValueKind wanted = flag ? ValueKind::Bool : ValueKind::Number;
    if (!value.is(wanted)) {
      fail(option.span,
           who + "option '" + name + "' must be " + (flag ? "true or false" : "a number") + ", got " +
               kind_with_article(value.kind()),
           kOptionsHint);
    }
    auto out_of_range = [&](const std::string& range) {
      fail(option.span,
           who + "option '" + name + "' must be " + range + " (got " + format_for_message(value.as_number()) +
               ")",
           kOptionsHint);
    };
    if (name == "crease") {
      options.crease_angle_deg = value.as_number();
      if (!(options.crease_angle_deg >= 0 && options.crease_angle_deg <= 180))
        out_of_range("from 0 to 180 degrees");
    } else if (name == "planarity") {
      options.planarity_tolerance = value.as_number();
      if (!(options.planarity_tolerance > 0 && options.planarity_tolerance <= kMaxPlanarity))
        out_of_range("above 0 and at most 0.05");
    } else if (name == "crossing_holes") {
      options.allow_crossing_holes = value.as_bool();
    } else {
      options.fix_winding = value.as_bool();
    }
  }
  return options;
}

}  // namespace

void Evaluator::exec_solid(const lang::SolidStmt& solid, const ScopePtr& scope) {
  SolidBuilder builder(build_options(solid, [&](const lang::Expr& e) { return eval(e, scope); }));
  std::vector<lang::SourceSpan> item_spans;  // builder tag → span
  std::size_t faces = 0;
  for (const lang::SolidItem& item : solid.items) {
    const auto tag = static_cast<std::int64_t>(item_spans.size());
    item_spans.push_back(item.span);
    std::visit(
        Overloaded{
            [&](const lang::VertexDecl& v) {
              if (v.literal) {
                const auto& [x, y, z] = *v.literal;
                builder.add_vertex(vertex_key(v.id), Point3{x, y, z}, tag);
                return;
              }
              const Value p = eval(*v.position, scope);
              if (!p.is(ValueKind::Vector))
                fail(v.position->span,
                     "vertex " + v.id.text + " needs a position vector, got " + kind_with_article(p.kind()),
                     "for example: vertex " + v.id.text + " = (0, 10, 5)");
              builder.add_vertex(vertex_key(v.id), to_point(p.as_vector()), tag);
            },
            [&](const lang::FaceDecl& f) {
              ++faces;
              const std::vector<std::string> outer = vertex_keys(f.ids);
              if (f.holes.empty() && revisits_a_vertex(outer)) {
                builder.add_face_loop(outer, tag);
                return;
              }
              std::vector<std::vector<std::string>> holes;
              for (const lang::HoleLoop& h : f.holes) holes.push_back(vertex_keys(h.ids));
              builder.add_face(outer, holes, tag);
            },
            [&](const lang::LineDecl& l) { builder.add_line(vertex_key(l.from), vertex_key(l.to), tag); },
        },
        item.node);
  }
  budget_.charge_faces_built(solid.name.span, faces);
  budget_.step(solid.name.span, solid.items.size());

  SolidBuildResult result = builder.build();
  // What the script's own options asked to accept (a raised planarity, crossing holes) is a note, shown
  // with --verbose: legacy data known to be warped should not warn on every run.
  auto given = [&](std::string_view option) {
    return std::any_of(solid.options.begin(), solid.options.end(),
                       [&](const lang::Argument& a) { return a.label && a.label->text == option; });
  };
  const bool accepted_warps = given("planarity"), accepted_holes = given("crossing_holes");
  std::vector<lang::Diagnostic> errors;
  for (const SolidDiagnostic& sd : result.diagnostics) {
    lang::Diagnostic d;
    d.severity =
        sd.severity == SolidDiagnostic::Severity::Error ? lang::Severity::Error : lang::Severity::Warning;
    if (d.severity == lang::Severity::Warning &&
        ((sd.code == "non-planar" && accepted_warps) || (sd.code == "bad-hole" && accepted_holes)))
      d.severity = lang::Severity::Note;
    const bool tagged = sd.tag >= 0 && static_cast<std::size_t>(sd.tag) < item_spans.size();
    d.span = tagged ? item_spans[static_cast<std::size_t>(sd.tag)] : solid.name.span;
    d.message = "solid '" + solid.name.text + "': " + sd.message;
    (d.severity == lang::Severity::Error ? errors : out_.warnings).push_back(std::move(d));
  }
  if (!result.ok()) {
    if (errors.empty()) fail(solid.name.span, "solid '" + solid.name.text + "' cannot be built");
    const std::string summary = errors.front().message;
    throw EvalError(std::move(errors), ErrorKind::Script, summary);
  }
  define(scope, solid.name,
         Value::solid(std::make_shared<const Solid>(std::move(*result.solid)), solid.name.text));
}

}  // namespace hlr::runtime
