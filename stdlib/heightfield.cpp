// heightfield(): a terrain over a regular grid, as an open surface or, with a base, a closed block. Only
// coplanar cells stay quads; the rest are split into two triangles, so every face is planar exactly.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/tolerance.hpp"
#include "stdlib/generator_detail.hpp"
#include "stdlib/generators.hpp"
#include "stdlib/shapes.hpp"

namespace hlr::stdlib {

using detail::require;

Solid heightfield(const std::vector<std::vector<double>>& heights, double dx, double dy,
                  std::optional<double> base, double crease_angle_deg) {
  const char* fn = "heightfield";
  require(heights.size() >= 2, fn, "values need at least 2 rows");
  const std::size_t rows = heights.size(), cols = heights[0].size();
  require(cols >= 2, fn, "every row of values needs at least 2 heights");
  double lowest = heights[0][0], highest = heights[0][0];
  for (std::size_t i = 0; i < rows; ++i) {
    require(heights[i].size() == cols, fn,
            "row " + std::to_string(i) + " of values has " + std::to_string(heights[i].size()) +
                " heights, row 0 has " + std::to_string(cols) + "; rows must be equally long");
    for (double h : heights[i]) {
      require(std::isfinite(h), fn, "values must be finite");
      lowest = std::min(lowest, h);
      highest = std::max(highest, h);
    }
  }
  require(std::isfinite(dx) && dx > 0, fn, "dx must be positive");
  require(std::isfinite(dy) && dy > 0, fn, "dy must be positive");
  require(!base || (std::isfinite(*base) && *base < lowest), fn, "base must be below every height");
  // Grid points (and the base) closer than the builder's coincidence tolerance would merge.
  const double extent = std::max({std::abs(lowest), std::abs(highest), base ? std::abs(*base) : 0.0,
                                  static_cast<double>(cols - 1) * dx, static_cast<double>(rows - 1) * dy});
  require(std::min(dx, dy) > Tolerance::kGeneratorFeature * extent, fn,
          "dx and dy are too small next to the heights");
  require(!base || lowest - *base > Tolerance::kGeneratorFeature * extent, fn,
          "base is too close below the lowest height");
  require(std::isfinite(crease_angle_deg) && crease_angle_deg >= 0 && crease_angle_deg <= 180, fn,
          "crease must lie in [0, 180]");

  std::vector<Point3> vertices;
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t j = 0; j < cols; ++j)
      vertices.push_back({static_cast<double>(j) * dx, static_cast<double>(i) * dy, heights[i][j]});
  auto id = [cols](std::size_t i, std::size_t j) { return static_cast<std::uint32_t>(i * cols + j); };

  // Cell corners a, b, c, d counter-clockwise seen from above (+x, then +y). The cell is planar when its
  // diagonals' midpoints coincide: h(a) + h(c) = h(b) + h(d), up to rounding of the heights' size.
  const double scale = std::max(std::abs(lowest), std::abs(highest)) + dx + dy;
  std::vector<IndexedFace> faces;
  for (std::size_t i = 0; i + 1 < rows; ++i)
    for (std::size_t j = 0; j + 1 < cols; ++j) {
      const std::uint32_t a = id(i, j), b = id(i, j + 1), c = id(i + 1, j + 1), d = id(i + 1, j);
      const double warp = vertices[a].z + vertices[c].z - vertices[b].z - vertices[d].z;
      if (std::abs(warp) <= Tolerance::kHeightfieldWarp * scale) {
        faces.push_back(IndexedFace{{a, b, c, d}});
      } else {
        faces.push_back(IndexedFace{{a, b, c}});
        faces.push_back(IndexedFace{{a, c, d}});
      }
    }
  if (!base) return solid_from_indexed(vertices, faces, crease_angle_deg);

  // The block: four walls, each one polygon in its side plane (base corners, then the terrain's border
  // walked back), counter-clockwise seen from outside, and the bottom.
  const double x1 = static_cast<double>(cols - 1) * dx, y1 = static_cast<double>(rows - 1) * dy;
  const auto b00 = static_cast<std::uint32_t>(vertices.size());
  const std::uint32_t b10 = b00 + 1, b11 = b00 + 2, b01 = b00 + 3;  // bXY: X, Y ∈ {0: low, 1: high}
  vertices.push_back({0, 0, *base});
  vertices.push_back({x1, 0, *base});
  vertices.push_back({x1, y1, *base});
  vertices.push_back({0, y1, *base});
  IndexedFace front{{b00, b10}}, right{{b10, b11}}, back{{b11, b01}}, left{{b01, b00}};
  for (std::size_t j = cols; j-- > 0;) front[0].push_back(id(0, j));
  for (std::size_t i = rows; i-- > 0;) right[0].push_back(id(i, cols - 1));
  for (std::size_t j = 0; j < cols; ++j) back[0].push_back(id(rows - 1, j));
  for (std::size_t i = 0; i < rows; ++i) left[0].push_back(id(i, 0));
  faces.insert(faces.end(), {front, right, back, left, IndexedFace{{b00, b01, b11, b10}}});
  return solid_from_indexed(vertices, faces, crease_angle_deg);
}

}  // namespace hlr::stdlib
