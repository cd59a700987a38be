// Distorted planes for contour shaking (SPEC 1.4; Lee §4.2, Eq. 2; Pacheco §3), and the
// parameters of multiple contour drawing (SPEC 2.4).
// For copy k, at the grid vertex (x, y) (one every grid_cell pixels) the offset is
//   dx_k = a sin(b y + c_k) + r xi_k(x, y),   dy_k = a sin(b x + c'_k) + r eta_k(x, y)
// with b = 2 pi / shake_period, phases and xi, eta in [-1, 1] from the seeded RNG. Inside
// a cell the offset is the bilinear interpolation of its corners (GL_LINEAR, clamp).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "common/image.hpp"
#include "common/scene.hpp"

namespace plumbago {

struct ContourParams {
  static constexpr const char* stage = "contour";
  int copies, grid_cell, texture_layer;
  float shake_amplitude, shake_period, shake_noise;
  float texture_scale, texture_strength, stroke_opacity;
  template <class V>
  void visit(V& v) {
    v.integer(copies, "copies", 3, 1, 8, "contour copies drawn on distorted planes (paper: 3-5)");
    v.integer(grid_cell, "grid_cell", 16, 2, 512, "pixels between vertices of the distortion grid");
    v.integer(texture_layer, "texture_layer", 20, 0, 255, "layer of the pencil stack used as contour texture");
    v.real(shake_amplitude, "shake_amplitude", 2.0, 0.0, 64.0, "a of Eq. 2: sine amplitude, pixels");
    v.real(shake_period, "shake_period", 120.0, 1.0, 100000.0, "2 pi / b of Eq. 2: sine period, pixels");
    v.real(shake_noise, "shake_noise", 0.6, 0.0, 64.0, "r of Eq. 2: random offset amplitude, pixels");
    v.real(texture_scale, "texture_scale", 1.0, 0.05, 64.0, "window pixels per contour-texture texel");
    v.real(texture_strength, "texture_strength", 0.6, 0.0, 1.0, "how much the contour texture breaks up a stroke");
    v.real(stroke_opacity, "stroke_opacity", 0.7, 0.0, 1.0, "alpha: darkness one contour copy lays down");
  }
};

// Offset grid of copy k: RG (dx, dy) in pixels, (ceil(W / cell) + 1) x (ceil(H / cell) + 1).
std::vector<Image> distortion_grids(const ContourParams& p, int width, int height, uint32_t seed);

// o_k: a seeded shift of copy k's contour texture, in texels (SPEC 2.4).
std::vector<glm::vec2> contour_texture_shifts(const ContourParams& p, uint32_t seed);

// The largest |dx| or |dy| of any grid (bilinear interpolation stays within it).
float largest_offset(const std::vector<Image>& grids);

// Where multiple contour drawing can differ from 0 (SPEC 2.4): a copy reads d' within the
// largest offset, d' differs from the background's within the edge filter's pixel of the
// objects (common/scene.hpp covered_rect), and the bilinear read adds one. The whole
// window when the background's d is not 0 (edge.background_pairs = formula).
PixelRect contour_rect(const Scene& scene, const std::vector<Image>& grids);

}  // namespace plumbago
