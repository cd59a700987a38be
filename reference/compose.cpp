#include "reference/compose.hpp"

#include <algorithm>

namespace plumbago::reference {

namespace {

float smoothstep01(float x) {
  float t = std::clamp(x, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// I = (1 - D_c)(1 - D_i'), D_i' = D_i (1 - a D_c)  (Eq. 6)
float composed_intensity(float contour_darkness, float interior_darkness, const ComposeParams& p) {
  float attenuated = interior_darkness * (1.0f - p.contour_attenuation * contour_darkness);
  return (1.0f - contour_darkness) * (1.0f - attenuated);
}

// I'' = mix(I, smoothstep(0, 1, I), contrast)
float enhanced(float i, const ComposeParams& p) { return i + (smoothstep01(i) - i) * p.contrast; }

}  // namespace

Image compose(const Image& contour_darkness, const ComposeParams& p) {
  Image out(contour_darkness.width, contour_darkness.height, 3);
  for (size_t i = 0; i < out.pixels(); ++i) {
    float v = enhanced(composed_intensity(contour_darkness.data[i], 0.0f, p), p);
    for (int c = 0; c < 3; ++c) out.data[i * 3 + c] = v;  // x paper color c_p = white
  }
  return out;
}

}  // namespace plumbago::reference
