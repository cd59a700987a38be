// Contour lighting (Lee §4.1, Eq. 1): lit contours are drawn lighter.
//   d' = d l_c,   l_c = 1 - lambda min(1, sum_lights intensity max(0, N.L))
// N the pixel's view-space shading normal (0 on the background: unlit), L the view-space
// light directions. Reading (Lee et al. 2006, §4.1, Eq. 1): Eq. 1 scales darkness, not the gray value.
#pragma once

#include "common/core/stage.hpp"
#include "common/pencil/edge_detect.hpp"
#include "common/scene/gbuffer.hpp"

namespace plumbago {

struct ContourLightParams {
  static constexpr const char* stage = "contour_light";
  float light_influence;
  template <class V>
  void visit(V& v) {
    v.real(light_influence, "light_influence", 0.5, 0.0, 1.0,
           "lambda: how much light lightens a contour, l_c = 1 - lambda N.L (Lee Eq. 1)");
  }
};

inline constexpr Buffer kLitContourDarkness{"contour_light.lit_contour_darkness"};  // d'

struct ContourLightStage {
  using Params = TypeList<ContourLightParams>;
  static StageDesc describe() {
    return {.name = "contour_light",
            .kind = StageKind::Frame,
            .doc = "lit contours drawn lighter (Lee et al. 2006, §4.1, Eq. 1)",
            .params = {"contour_light"},
            .inputs = {{.handle = kContourDarkness}, {.handle = kGBuffer.normal}},
            .outputs = {{.handle = kLitContourDarkness,
                         .doc = "d' = d l_c",
                         .tolerance = tolerance::kFloat,
                         .tolerance_why = "fed the same d and G-buffer; float target"}}};
  }
};

}  // namespace plumbago
