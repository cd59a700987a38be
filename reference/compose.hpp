// Composition, CPU reference (SPEC 2.11).
#pragma once

#include "common/compose.hpp"
#include "common/image.hpp"

namespace plumbago::reference {

// RGB output from contour darkness D_c (no interior strokes, white paper: D_i = 0, c_p = 1).
Image compose(const Image& contour_darkness, const ComposeParams& p);

}  // namespace plumbago::reference
