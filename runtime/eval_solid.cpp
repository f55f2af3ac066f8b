// solid NAME { vertex ... face ... line ... }: the items go to hlr::SolidBuilder, each tagged with its
// index so that every builder diagnostic (non-planar face, unknown vertex, ...) points at its item.
// Errors fail the statement, all of them reported together; warnings (a reoriented face) are kept
// with the frame and printed once.
#include <algorithm>
#include <map>

#include "core/solid/solid_builder.hpp"
#include "runtime/eval_detail.hpp"
#include "runtime/evaluator.hpp"

namespace hlr::runtime {

namespace {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

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

// A face whose id list comes back to a vertex it left (not just a vertex repeated in a row) is a loop
// in the theses' style (Desens' LSTFAC): edges walked both ways are bridges or lines on the face.
bool revisits_a_vertex(const std::vector<std::string>& ids) {
  std::map<std::string, int> seen;
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (i == 0 || ids[i] != ids[i - 1]) ++seen[ids[i]];
  if (ids.size() > 1 && ids.front() == ids.back()) --seen[ids.front()];  // written closed: 1 2 3 1
  return std::any_of(seen.begin(), seen.end(), [](const auto& e) { return e.second > 1; });
}

}  // namespace

void Evaluator::exec_solid(const lang::SolidStmt& solid, const ScopePtr& scope) {
  SolidBuilder builder;
  std::vector<lang::SourceSpan> item_spans;  // builder tag → span
  std::size_t faces = 0;
  for (const lang::SolidItem& item : solid.items) {
    const auto tag = static_cast<std::int64_t>(item_spans.size());
    item_spans.push_back(item.span);
    std::visit(
        Overloaded{
            [&](const lang::VertexDecl& v) {
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
  std::vector<lang::Diagnostic> errors;
  for (const SolidDiagnostic& sd : result.diagnostics) {
    lang::Diagnostic d;
    d.severity =
        sd.severity == SolidDiagnostic::Severity::Error ? lang::Severity::Error : lang::Severity::Warning;
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
