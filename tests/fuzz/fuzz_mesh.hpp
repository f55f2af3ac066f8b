// Shared by the mesh importer targets: runs one import, for which MeshImportError is the expected way
// to refuse bad data; anything else escaping, or a solid that is not whole, is a finding. A small face
// limit keeps each input quick.
#pragma once

#include <cstdlib>

#include "stdlib/mesh_import.hpp"

namespace hlr::fuzz {

inline stdlib::MeshImportOptions mesh_options() {
  stdlib::MeshImportOptions options;
  options.max_faces = 20'000;
  return options;
}

// A solid the importer returns is whole: finite vertices, rings of at least three of them, one plane per
// face, edges between existing vertices and faces, and no more faces than the limit (after repairs).
inline bool well_formed(const Solid& solid) {
  const std::size_t vertices = solid.vertices.size(), faces = solid.faces.size();
  if (faces > mesh_options().max_faces || solid.planes.size() != faces) return false;
  for (const Point3& p : solid.vertices)
    if (!is_finite(p)) return false;
  for (const Face& face : solid.faces) {
    if (face.rings.empty()) return false;
    for (const Ring& ring : face.rings) {
      if (ring.vertices.size() < 3) return false;
      for (const VertexIndex v : ring.vertices)
        if (v >= vertices) return false;
    }
  }
  const auto face_ok = [&](FaceIndex f) {
    return f == kNoFace || (f >= 0 && static_cast<std::size_t>(f) < faces);
  };
  for (const SolidEdge& e : solid.edges)
    if (e.v0 >= vertices || e.v1 >= vertices || !face_ok(e.left) || !face_ok(e.right)) return false;
  return true;
}

template <typename Import>
void import_or_refuse(Import&& import) {
  try {
    const stdlib::ImportedMesh mesh = import(mesh_options());
    if (!well_formed(mesh.solid)) std::abort();
  } catch (const stdlib::MeshImportError& e) {
    if (e.problem.message.empty()) std::abort();  // a refusal says why
  }
}

}  // namespace hlr::fuzz
