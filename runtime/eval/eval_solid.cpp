// solid NAME (OPTIONS) { vertex ... face ... line ... }: the options become hlr::SolidBuildOptions, the
// items go to hlr::SolidBuilder, each tagged with its index so that every builder diagnostic
// (non-planar face, unknown vertex, ...) points at its item. Errors fail the statement, all of them
// reported together; warnings (a reoriented face) are kept with the frame and printed once.
#include <algorithm>
#include <array>
#include <span>
#include <string_view>

#include "core/format_number.hpp"
#include "core/solid/solid_builder.hpp"
#include "lang/overloaded.hpp"
#include "runtime/eval/eval_detail.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/values/format_value.hpp"

namespace hlr::runtime {

namespace {

using lang::Overloaded;

constexpr std::size_t kFewIds = 16;
constexpr std::uint32_t kUndeclared = 0xffffffffu;

// A face whose id list comes back to a vertex it left (not just a vertex repeated in a row) is a loop
// in the theses' style (Desens' LSTFAC): edges walked both ways are bridges or lines on the face.
bool revisits_a_vertex(std::span<const std::uint32_t> ids) {
  // The walk with repeats in a row collapsed and, when written closed (1 2 3 1), the closing id dropped.
  thread_local std::vector<std::uint32_t> walk;
  walk.clear();
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

// The vertex each id of the block declares, when every id is declared exactly once and every id used is
// declared: then the builder can take numbers. Otherwise (a mistake it must report by name) empty.
std::vector<std::uint32_t> declared_vertices(const lang::SolidBody& body) {
  std::vector<std::uint32_t> vertex_of(body.id_count(), kUndeclared);
  for (std::size_t k = 0; k < body.vertices().size(); ++k) {
    std::uint32_t& slot = vertex_of[body.vertices()[k].id];
    if (slot != kUndeclared) return {};
    slot = static_cast<std::uint32_t>(k);
  }
  for (std::size_t f = 0; f < body.face_count(); ++f)
    for (std::size_t r = 0; r < body.ring_count(f); ++r)
      for (const std::uint32_t id : body.ring(f, r))
        if (vertex_of[id] == kUndeclared) return {};
  for (const auto& [a, b] : body.lines())
    if (vertex_of[a] == kUndeclared || vertex_of[b] == kUndeclared) return {};
  return vertex_of;
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

// The items go to the builder in the order written, each tagged with its place among them. When every id
// is declared once and every id used is declared (always, in working scripts), they go as vertex numbers
// with the ids kept only to name vertices in messages; otherwise as the ids themselves, which the
// builder then reports on.
void Evaluator::exec_solid(const lang::SolidStmt& solid, const ScopePtr& scope) {
  const lang::SolidBody& body = solid.body;
  SolidBuilder builder(build_options(solid, [&](const lang::Expr& e) { return eval(e, scope); }));
  const std::vector<std::uint32_t> vertex_of = declared_vertices(body);
  const bool indexed = !vertex_of.empty() || body.id_count() == 0;
  if (indexed)
    builder.label_indexed_vertices(
        [&](VertexIndex v) { return std::string(body.id(body.vertices()[v].id)); });
  builder.reserve(body.vertices().size(), body.face_count(), body.reference_count(), true);
  const auto key = [&](std::uint32_t id) { return std::string(body.id(id)); };
  std::vector<VertexIndex> ring;
  std::size_t vertex = 0, face = 0, line = 0;
  for (std::size_t item = 0; item < body.items().size(); ++item) {
    const auto tag = static_cast<std::int64_t>(item);
    switch (body.items()[item].kind) {
      case lang::SolidBody::ItemKind::Vertex: {
        const lang::SolidBody::Vertex& v = body.vertices()[vertex++];
        Point3 at{v.at[0], v.at[1], v.at[2]};
        if (v.position != lang::SolidBody::kLiteral) {
          const lang::Expr& position = body.position(v);
          const Value p = eval(position, scope);
          const std::string id = key(v.id);
          if (!p.is(ValueKind::Vector))
            fail(position.span,
                 "vertex " + id + " needs a position vector, got " + kind_with_article(p.kind()),
                 "for example: vertex " + id + " = (0, 10, 5)");
          at = to_point(p.as_vector());
        }
        if (indexed)
          builder.add_vertex(at, tag);
        else
          builder.add_vertex(key(v.id), at, tag);
        break;
      }
      case lang::SolidBody::ItemKind::Face: {
        const std::size_t rings = body.ring_count(face);
        const bool loop = rings == 1 && revisits_a_vertex(body.ring(face, 0));
        if (indexed && rings == 1) {
          ring.clear();
          for (const std::uint32_t id : body.ring(face, 0)) ring.push_back(vertex_of[id]);
          if (loop)
            builder.add_indexed_face_loop(ring, tag);
          else
            builder.add_indexed_polygon(ring, tag);
        } else if (indexed) {
          std::vector<std::vector<VertexIndex>> all(rings);
          for (std::size_t r = 0; r < rings; ++r)
            for (const std::uint32_t id : body.ring(face, r)) all[r].push_back(vertex_of[id]);
          builder.add_indexed_face(all, tag);
        } else {
          auto texts = [&](std::size_t r) {
            std::vector<std::string> out;
            for (const std::uint32_t id : body.ring(face, r)) out.push_back(key(id));
            return out;
          };
          if (loop) {
            builder.add_face_loop(texts(0), tag);
          } else {
            std::vector<std::vector<std::string>> holes;
            for (std::size_t r = 1; r < rings; ++r) holes.push_back(texts(r));
            builder.add_face(texts(0), holes, tag);
          }
        }
        ++face;
        break;
      }
      case lang::SolidBody::ItemKind::Line: {
        const auto& [a, b] = body.lines()[line++];
        if (indexed)
          builder.add_indexed_line(vertex_of[a], vertex_of[b], tag);
        else
          builder.add_line(key(a), key(b), tag);
        break;
      }
    }
  }
  budget_.charge_faces_built(solid.name.span, body.face_count());
  budget_.step(solid.name.span, body.items().size());

  SolidBuildResult result = builder.build();
  // What the script's own options asked to accept (a raised planarity, crossing holes) is a note, shown
  // with --verbose: legacy data known to be warped should not warn on every run.
  auto given = [&](std::string_view option) {
    return std::any_of(solid.options.begin(), solid.options.end(),
                       [&](const lang::Argument& a) { return a.label && a.label->text == option; });
  };
  const bool accepted_warps = given("planarity"), accepted_holes = given("crossing_holes");
  std::vector<lang::Diagnostic> errors;
  const lang::SourceFile* file = sources_.file(body.file());
  for (const SolidDiagnostic& sd : result.diagnostics) {
    lang::Diagnostic d;
    d.severity =
        sd.severity == SolidDiagnostic::Severity::Error ? lang::Severity::Error : lang::Severity::Warning;
    if (d.severity == lang::Severity::Warning &&
        ((sd.code == "non-planar" && accepted_warps) || (sd.code == "bad-hole" && accepted_holes)))
      d.severity = lang::Severity::Note;
    d.span = solid.name.span;
    if (sd.tag >= 0 && static_cast<std::size_t>(sd.tag) < body.items().size() && file) {
      const lang::SolidBody::Item& item = body.items()[static_cast<std::size_t>(sd.tag)];
      d.span = file->span(item.begin, item.end);
    }
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
