// Occlusion levels against the RayCaster oracle, which counts every face its sight line crosses before a
// point (RayCaster::surfaces_in_front; nothing of the engine is reused):
//   (a) every returned piece's interior samples have exactly the piece's level (0 for visible pieces);
//   (b) every sample of a drawn-candidate edge — back edges included, since levels cull nothing — whose
//       count is 1 … max_level lies on a returned piece of that edge with that level, and one whose count
//       is past max_level lies on none.
// Samples the oracle calls ambiguous (within its tolerance of a face's outline or plane) are skipped.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/hlr/scene.hpp"
#include "core/hlr/visible_segment.hpp"
#include "tests/support/ray_caster.hpp"

namespace hlr::test {

struct LevelReport {
  std::size_t piece_samples = 0, piece_wrong = 0;                                          // (a)
  std::size_t edge_samples = 0, edge_hidden = 0, edge_missing = 0, edge_beyond_drawn = 0;  // (b)
  std::size_t ambiguous = 0;
  std::vector<std::size_t> samples_per_level;  // (b) hidden samples by oracle count, 0 … max_level
  std::vector<std::string> failures;           // the first few, one line each
  bool ok() const { return piece_wrong == 0 && edge_missing == 0 && edge_beyond_drawn == 0; }
  std::string summary() const;
};

LevelReport check_occlusion_levels(const Scene& scene, const RayCaster& oracle, const FrameResult& result,
                                   unsigned max_level, int edge_samples = 17);

}  // namespace hlr::test
