// Built-in thesis models: Desens' L-shaped block (12 nodes, 8 faces, 18 lines) and aircraft carrier
// (62 nodes, 32 faces, 93 lines), in the thesis's object coordinates.
#pragma once

#include "core/solid/solid.hpp"

namespace hlr::stdlib {

Solid desens_lblock();
Solid desens_carrier();

}  // namespace hlr::stdlib
