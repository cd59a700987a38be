// Procedural meshes for the built-in scenes and the analytic test surfaces.
#pragma once

#include <string>
#include <vector>

#include "common/mesh/mesh.hpp"

namespace plumbago {

// Kinds: "torus", "sphere", "cad" (a part with sharp creases next to smooth patches),
// "plane", "cylinder", "cube", "storefront" (a brick facade of many boxes: Kalnins et al.
// 2002's building). `resolution` scales the tessellation (1 = default).
Mesh make_procedural(const std::string& kind, float resolution = 1.0f);
// The kinds above, in that order.
const std::vector<std::string>& procedural_kinds();

}  // namespace plumbago
