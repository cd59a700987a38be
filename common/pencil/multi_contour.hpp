// Multiple contour drawing (Lee §4.2-4.3, Pacheco §4): the copies of the lit
// contours, each read through its distorted plane (common/pencil/distortion.hpp) and broken up
// by the contour texture (common/pencil/contour_texture.hpp):
//   d_k = d'(p + offset_k(p)),  t_k = 1 - T_c(p / texture_scale + o_k)
//   D_c = 1 - prod_k (1 - alpha d_k mix(1, t_k, texture_strength))
#pragma once

#include <vector>

#include "common/core/stage.hpp"
#include "common/pencil/contour_light.hpp"
#include "common/pencil/contour_texture.hpp"
#include "common/scene/scene.hpp"
#include "common/util/image.hpp"

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

// Where multiple contour drawing can differ from 0 (Lee et al. 2006, §4.2-4.3): a copy reads d' within the
// largest offset, d' differs from the background's within the edge filter's pixel of the
// objects (common/scene/scene.hpp covered_rect), and the bilinear read adds one. The whole
// window when the background's d is not 0 (edge.background_pairs = formula).
PixelRect contour_rect(const Scene& scene, const std::vector<Image>& grids);

// What the distortion preprocessing (common/pencil/distortion.hpp) makes of ContourParams.
inline constexpr Slot<std::vector<Image>> kOffsetGrids{"distortion.offset_grids"};
inline constexpr Slot<std::vector<glm::vec2>> kTextureShifts{"distortion.texture_shifts"};  // o_k
inline constexpr Buffer kCopiesDarkness{"multi_contour.contour_darkness"};                  // D_c

struct MultiContourStage {
  using Params = TypeList<ContourParams>;
  static StageDesc describe() {
    return {.name = "multi_contour",
            .kind = StageKind::Frame,
            .doc = "contour copies on distorted planes with the contour texture (Lee et al. 2006, §4.2-4.3)",
            .params = {"contour"},
            .inputs = {{.handle = kLitContourDarkness},
                       {.handle = kOffsetGrids},
                       {.handle = kTextureShifts},
                       {.handle = kContourTexture}},
            .outputs = {{.handle = kCopiesDarkness,
                         .doc = "D_c of all copies",
                         .tolerance = tolerance::kSampled,
                         .tolerance_why = "fed the same d', offset grids and contour texture; bilinear lookups"}}};
  }
};

}  // namespace plumbago
