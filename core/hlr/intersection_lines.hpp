// Lines where faces cross: of different solids (interpenetrating solids) and of one solid (parts of one
// mesh that interpenetrate; Solid::self_crossings). Each piece strictly inside both faces becomes a
// candidate edge, examined for visibility like any other. Lines on a back face of a
// closed solid are hidden by the solid itself: they are made only when `keep_culled` asks for them.
#pragma once

#include <cstdint>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/hlr/frame_setup.hpp"
#include "core/hlr/scene.hpp"

namespace hlr {

void add_intersection_candidates(const Scene& scene, const Camera& camera,
                                 const std::vector<std::vector<std::int8_t>>& facing, const std::vector<char>& cull,
                                 double length_tolerance, bool keep_culled, FrameSetup& setup);

}  // namespace hlr
