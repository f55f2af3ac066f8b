// Mesh export: the solids a frame draws, in world coordinates, as a mesh file another tool reads — a slicer
// for 3-D printing, a mesh checker, a modeller. The inverse of mesh_import.hpp, in the same three formats:
//   - OFF: the vertices, then each face as one polygon (its outline ring);
//   - OBJ: an `o NAME` group per solid, its vertices (`v`) and faces (`f`, 1-based, counting from the
//     file's first vertex);
//   - STL: binary, each face as triangles with its outward unit normal (STL holds triangles only).
// Faces with holes are written as triangles in OFF and OBJ too (neither has holes): a constrained Delaunay
// triangulation of the face's rings (stdlib/booleans.hpp), so a drilled plate stays a closed surface. Only
// vertices on a face are written (a marking's or hatch line's ends are not part of the surface); solids
// with no faces (free lines only) are left out. Faces keep their orientation: counter-clockwise seen from
// outside, as all three formats expect.
//
// Coordinates are written so they read back to the same double (OFF, OBJ) or as the nearest float (STL,
// whose format has no other).
#pragma once

#include <memory>
#include <string>

#include "core/device/page/device.hpp"
#include "core/hlr/scene.hpp"

namespace hlr::stdlib {

enum class MeshFormat { Off, Obj, Stl };

// The file's bytes; `title` goes into OFF's and OBJ's comment and STL's 80-byte header. Throws
// DeviceError for a coordinate that is not finite, or a scene of more faces than STL's count holds.
std::string mesh_file_bytes(const Scene& scene, MeshFormat format, const std::string& title);

// The device for `-o NAME.off|.obj|.stl`: one frame per file (DeviceFrame::scene, its drawn solids).
std::unique_ptr<Device> make_mesh_device(MeshFormat format, const std::string& title);

}  // namespace hlr::stdlib
