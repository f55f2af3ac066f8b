// The built-in demo (hlrscript --demo) is a script like any other, run on the normal path.
#pragma once

#include <string>

namespace hlr::runtime {

// Desens' aircraft carrier: an overview from 500 ft, then `approach_frames` frames of the landing
// approach of the thesis's Figures 36–39, interpolated between its printed views.
std::string demo_script(int approach_frames);

}  // namespace hlr::runtime
