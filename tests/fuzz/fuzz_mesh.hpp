// Shared by the mesh importer targets: runs one import, for which MeshImportError is the expected way
// to refuse bad data; anything else escaping is a finding. A small face limit keeps each input quick.
#pragma once

#include <cstdlib>

#include "stdlib/mesh_import.hpp"

namespace hlr::fuzz {

inline stdlib::MeshImportOptions mesh_options() {
  stdlib::MeshImportOptions options;
  options.max_faces = 20'000;
  return options;
}

template <typename Import>
void import_or_refuse(Import&& import) {
  try {
    const stdlib::ImportedMesh mesh = import(mesh_options());
    if (mesh.solid.faces.size() > mesh_options().max_faces) std::abort();  // the limit holds after repairs
  } catch (const stdlib::MeshImportError& e) {
    if (e.problem.message.empty()) std::abort();  // a refusal says why
  }
}

}  // namespace hlr::fuzz
