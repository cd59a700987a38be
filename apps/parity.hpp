// Stage parity (SPEC §5): each stage of both backends fed the same inputs, compared
// pixel by pixel. The G-buffer is the exception: raster vs ray tracing, compared on
// interior pixels, with the one-pixel band along depth discontinuities excluded and its
// share reported.
#pragma once

#include <string>
#include <vector>

#include "common/image_compare.hpp"
#include "common/scene.hpp"

namespace plumbago {

struct StageParity {
  std::string name;
  ImageDiff diff;
  bool pass = false;
  Image reference, gpu;  // what was compared (the heat map is made on request)
  std::string note;      // what was excluded, and why the tolerance is what it is
};

// Stage names `run_parity` knows, in pipeline order.
std::vector<std::string> parity_stages();

// Runs the parity check of each named stage (all when empty) on `scene`. Throws
// std::invalid_argument naming an unknown stage.
std::vector<StageParity> run_parity(const Scene& scene, const std::vector<std::string>& stages = {});

// Pixels where both G-buffers hit the same object and no pixel of the 3x3 neighborhood
// (in either) lies across a depth discontinuity: another object, the background, or a
// linear-depth jump over 1%. 1 = interior, 0 = band or background.
struct GBuffer;
Image interior_mask(const GBuffer& a, const GBuffer& b);

}  // namespace plumbago
