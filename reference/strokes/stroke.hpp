// The stroke raster of the CPU reference (Kalnins et al. 2002, §4.1; formula in
// common/strokes/stroke.hpp): what its stroke stage draws, also for a caller with strokes of
// its own (experiments/temporal_coherence: coherent silhouettes).
#pragma once

#include <vector>

#include "common/strokes/stroke.hpp"
#include "common/strokes/stroke_paper.hpp"
#include "common/util/image.hpp"

namespace plumbago::reference {

// The ribbons `triangles` over `page`, fragment after fragment in order, with the stroke
// textures of `seed` and the paper of `paper_height`; per pixel also the fragments blended
// there and 1 where a triangle's edge passes within a subpixel of its center (another
// rasterizer's rounding may decide its coverage).
struct StrokeRaster {
  Image color, fragments, edges;
};
StrokeRaster draw_strokes(const std::vector<StrokeVertex>& triangles, uint32_t seed, const Image& page,
                          const Image& paper_height, const StrokePaperParams& paper);

}  // namespace plumbago::reference
