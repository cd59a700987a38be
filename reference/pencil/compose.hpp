// Composition, CPU reference (Lee et al. 2006, §6, Eq. 6).
#pragma once

#include "common/pencil/compose.hpp"
#include "common/util/image.hpp"

namespace plumbago::reference {

// RGB output from contour darkness D_c, interior darkness D_i (empty: no interior) and
// the paper color c_p read texel for pixel, wrapping (empty: white paper).
Image compose(const Image& contour_darkness, const Image& interior_darkness, const Image& paper_color,
              const ComposeParams& p);

}  // namespace plumbago::reference
