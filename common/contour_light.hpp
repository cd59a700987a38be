// Contour lighting (SPEC 2.3; Lee §4.1, Eq. 1): lit contours are drawn lighter.
//   d' = d l_c,   l_c = 1 - lambda min(1, sum_lights intensity max(0, N.L))
// N the pixel's view-space shading normal (0 on the background: unlit), L the view-space
// light directions. Reading (SPEC 2.3): Eq. 1 scales darkness, not the gray value.
#pragma once

namespace plumbago {

struct ContourLightParams {
  static constexpr const char* stage = "contour";
  float light_influence;
  template <class V>
  void visit(V& v) {
    v.real(light_influence, "light_influence", 0.5, 0.0, 1.0,
           "lambda: how much light lightens a contour, l_c = 1 - lambda N.L (Lee Eq. 1)");
  }
};

}  // namespace plumbago
