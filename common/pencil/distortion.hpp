// Distorted planes for contour shaking (Lee §4.2, Eq. 2; Pacheco §3).
// For copy k, at the grid vertex (x, y) (one every grid_cell pixels) the offset is
//   dx_k = a sin(b y + c_k) + r xi_k(x, y),   dy_k = a sin(b x + c'_k) + r eta_k(x, y)
// with b = 2 pi / shake_period, phases and xi, eta in [-1, 1] from the seeded RNG. Inside
// a cell the offset is the bilinear interpolation of its corners (GL_LINEAR, clamp).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "common/pencil/multi_contour.hpp"
#include "common/scene/scene.hpp"
#include "common/util/image.hpp"

namespace plumbago {

// Offset grid of copy k: RG (dx, dy) in pixels, (ceil(W / cell) + 1) x (ceil(H / cell) + 1).
std::vector<Image> distortion_grids(const ContourParams& p, int width, int height, uint32_t seed);

// o_k: a seeded shift of copy k's contour texture, in texels (Lee et al. 2006, §4.2-4.3).
std::vector<glm::vec2> contour_texture_shifts(const ContourParams& p, uint32_t seed);

// The largest |dx| or |dy| of any grid (bilinear interpolation stays within it).
float largest_offset(const std::vector<Image>& grids);

// kOffsetGrids and kTextureShifts: in common/pencil/multi_contour.hpp, which reads them.
struct Preprocessed;
struct DistortionStage {
  using Params = TypeList<>;
  static void make(const Scene& scene, Preprocessed& out);
  static StageDesc describe() {
    return {.name = "distortion",
            .kind = StageKind::Preprocessing,
            .doc = "offset grids of the contour copies (Lee et al. 2006, §4.2, Eq. 2)",
            .params = {"contour"},
            .outputs = {{.handle = kOffsetGrids,
                         .channels = 2,
                         .texel = Texel::Host,
                         .doc = "one RG grid of pixel offsets per contour copy"},
                        {.handle = kTextureShifts,
                         .channels = 2,
                         .texel = Texel::Host,
                         .doc = "o_k: the shift of copy k's contour texture, texels"}},
            .preprocess = make};
  }
};

}  // namespace plumbago
