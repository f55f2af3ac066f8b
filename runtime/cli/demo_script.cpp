#include "runtime/cli/demo_script.hpp"

namespace hlr::runtime {

std::string demo_script(int approach_frames) {
  const std::string n = std::to_string(approach_frames);
  return "# hlrscript --demo: Desens' aircraft carrier (1969), Carrier (1) and the approach of Carrier "
         "(2)-(5).\n"
         "animate frames " +
         std::to_string(approach_frames + 1) +
         " fps 8\n"
         "draw desens_carrier()\n"
         "# The ship steams -42 ft per printed view while the aircraft closes on the stern.\n"
         "let ship = [(126, 0, 0), (84, 0, 0), (42, 0, 0), (0, 0, 0)]\n"
         "let observer = [(1914, 151, 112.5), (1598, 96, 96), (1300, 43.5, 80), (950, 0, 66)]\n"
         "if frame == 0 {\n"
         "  camera overview = desens(object: (2000, 0, 0), attitude: (60, 0, 0), observer: (0, 0, 500),\n"
         "                           heading: (190, -5, 0))\n"
         "} else {\n"
         "  let u = (frame - 1) / max(1, " +
         n +
         " - 1) * 3\n"
         "  let k = min(floor(u), 2)\n"
         "  camera approach = desens(object: lerp(ship[k], ship[k + 1], u - k),\n"
         "                           observer: lerp(observer[k], observer[k + 1], u - k), heading: (10, 0, "
         "0))\n"
         "}\n";
}

}  // namespace hlr::runtime
