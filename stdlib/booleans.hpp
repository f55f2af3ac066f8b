// Booleans of solids: union, difference and intersection, computed exactly by CGAL's corefinement
// (Polygon Mesh Processing, on the exact-predicates-exact-constructions kernel) and returned as a validated
// solid. The one translation unit that includes CGAL is booleans.cpp, so the rest of the build stays fast.
//
// Each operand is triangulated (a face with holes by a constrained Delaunay triangulation of its rings),
// checked — closed, not crossing itself — and combined with the result so far, in exact arithmetic. The
// result's triangles that lie exactly in one plane are one face as far as the drawing goes: the edges
// between them are Flat, so no seam or triangulation edge is drawn, and curved surfaces keep their
// crease classification (the largest of the operands' crease angles).
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/solid/solid.hpp"

namespace hlr::stdlib {

enum class BooleanOp { Union, Difference, Intersection };

// An operand that cannot take part: `operand` is its index in the list given.
struct BooleanOperandError : std::runtime_error {
  BooleanOperandError(std::size_t operand_, const std::string& what)
      : std::runtime_error(what), operand(operand_) {}
  std::size_t operand;
};

// The combination of `operands` (already in one coordinate system), left to right: the union of all, the
// first minus all the others, or what all have in common. Throws BooleanOperandError for an operand that
// is not closed or crosses itself, std::runtime_error when the result is no valid solid (an empty
// intersection or difference: "the result is empty").
Solid boolean_solid(BooleanOp op, const std::vector<const Solid*>& operands);

// Appends the triangles of face f of s, counter-clockwise seen from outside, as vertex indices: the face's
// own triangle, or a constrained Delaunay triangulation of all its rings (holes and islands filled
// even-odd, as faces are) in exact predicates. Used by the booleans and by mesh export.
void face_triangles(const Solid& s, std::size_t f, std::vector<std::array<VertexIndex, 3>>& out);

}  // namespace hlr::stdlib
