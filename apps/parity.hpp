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

// SPEC §5 tolerances shared by the parity checks.
namespace parity_tolerance {
// Barycentrics, raster vs ray: the rasterizer snaps vertices to 1/2^GL_SUBPIXEL_BITS of a
// pixel (8 bits on llvmpipe), which moves a pixel's barycentrics by about
// (1/256 px) / (the triangle's extent in px): 1e-3 for a 4 px triangle. Measured max on the
// Stanford bunny at 800x800 (many 2-5 px triangles): 1.08e-3. Allowed: 4e-3 (1 px triangles).
constexpr double kBary = 4e-3;
constexpr double kFloat = 1e-4;  // a float stage fed identical inputs (measured ~1e-7)
constexpr double kByte = 2.0 / 255.0;
}  // namespace parity_tolerance

// One comparison; it passes when no pixel (within `mask`, if given) is over `tolerance`.
StageParity compared(std::string name, Image reference, Image gpu, double tolerance, const Image* mask, std::string note);

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
