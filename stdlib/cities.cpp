// Box cities: the benchmark scene of many mutually hiding solids (ln's skyscrapers, scaled up).
#include <array>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "stdlib/generator_detail.hpp"
#include "stdlib/generators.hpp"

namespace hlr::stdlib {

using detail::require;

namespace {

// Uniform in [a, b) from the raw 32-bit output of mt19937, whose sequence the standard fixes (the
// std::uniform_real_distribution algorithm is implementation-defined, so it is avoided).
double uniform(std::mt19937& rng, double a, double b) {
  return a + (b - a) * (static_cast<double>(rng()) / 4294967296.0);
}

// An exact rotation by k quarter turns about z (no rounding in cos/sin), about the origin.
Affine3 quarter_turn(int k) {
  static const std::array<std::array<double, 2>, 4> c = {{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}};  // (cos, sin)
  const double co = c[k & 3][0], si = c[k & 3][1];
  return Affine3::from_rows({co, -si, 0}, {si, co, 0}, {0, 0, 1});
}

// A tower on a podium: an L outline (x, z) extruded along y, fitted into the footprint [x0,x1]×[y0,y1]
// and turned by k quarter turns about its own vertical axis.
Solid tower(double x0, double y0, double x1, double y1, double height, int k, std::mt19937& rng) {
  double a = x1 - x0, b = y1 - y0;
  if (k & 1) std::swap(a, b);  // the L's own x extent lies along y after an odd number of quarter turns
  const double upright = a * uniform(rng, 0.35, 0.7), foot = height * uniform(rng, 0.15, 0.4);
  const std::vector<Point2> outline = {{0, 0},          {a, 0},      {a, foot},
                                       {upright, foot}, {upright, height}, {0, height}};
  // (u, v, w) → (u, b − w, v): the L's local frame (see l_block), then centre, turn and place.
  const Affine3 local = Affine3::from_rows({1, 0, 0}, {0, 0, -1}, {0, 1, 0}, {-0.5 * a, 0.5 * b, 0});
  const Affine3 place = Affine3::translation({0.5 * (x0 + x1), 0.5 * (y0 + y1), 0});
  return detail::extrude(outline, {}, 0, b, local.then(quarter_turn(k)).then(place));
}

}  // namespace

std::vector<Solid> box_city(int n_blocks_x, int n_blocks_y, unsigned seed, const CityOptions& o) {
  require(n_blocks_x >= 1 && n_blocks_y >= 1, "box_city", "needs at least one block each way");
  require(o.cell > o.street && o.street >= 0, "box_city", "cell must exceed street");
  require(o.min_height > 0 && o.max_height >= o.min_height, "box_city", "heights must be positive");
  std::mt19937 rng(seed);
  std::vector<Solid> city;
  city.reserve(static_cast<std::size_t>(n_blocks_x) * n_blocks_y + 1);
  const double free = o.cell - o.street;  // the largest footprint side
  for (int i = 0; i < n_blocks_x; ++i)
    for (int j = 0; j < n_blocks_y; ++j) {
      const double wx = free * uniform(rng, 0.5, 1), wy = free * uniform(rng, 0.5, 1);
      const double x0 = i * o.cell + 0.5 * o.street + uniform(rng, 0, 1) * (free - wx);
      const double y0 = j * o.cell + 0.5 * o.street + uniform(rng, 0, 1) * (free - wy);
      // Squared uniform: many low buildings, a few tall ones.
      const double u = uniform(rng, 0, 1);
      const double h = o.min_height + (o.max_height - o.min_height) * u * u;
      const bool is_tower = uniform(rng, 0, 1) < o.tower_chance;
      const int turn = static_cast<int>(rng() & 3);
      if (is_tower)
        city.push_back(tower(x0, y0, x0 + wx, y0 + wy, h, turn, rng));
      else
        city.push_back(box({x0, y0, 0}, {x0 + wx, y0 + wy, h}));
    }
  if (o.ground) {
    const double pad = 0.5 * o.cell;
    city.push_back(box({-pad, -pad, -0.1 * o.cell}, {n_blocks_x * o.cell + pad, n_blocks_y * o.cell + pad, 0}));
  }
  return city;
}

}  // namespace hlr::stdlib
