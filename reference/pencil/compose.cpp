#include "reference/pencil/compose.hpp"

#include <algorithm>

#include "reference/core/stage.hpp"

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

Image compose(const Image& contour_darkness, const Image& interior_darkness, const Image& paper_color,
              const ComposeParams& p) {
  Image out(contour_darkness.width, contour_darkness.height, 3);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      float d_i = interior_darkness.empty() ? 0.0f : interior_darkness.at(x, y);
      float v = enhanced(composed_intensity(contour_darkness.at(x, y), d_i, p), p);
      for (int c = 0; c < 3; ++c)  // out = I'' c_p
        out.at(x, y, c) =
            v * (paper_color.empty() ? 1.0f : paper_color.at(x % paper_color.width, y % paper_color.height, c));
    }
  return out;
}

// Composition reads what the effects made: no contours (D_c = 0), no interior, white paper.
PLUMBAGO_REFERENCE_STAGE(compose, [](ReferenceFrame& f) {
  const Image* contours = f.get(maybe(kCopiesDarkness));
  const Image* interior = f.get(maybe(kInteriorDarkness));
  const Image* paper_color = f.get(maybe(kPaperColor));
  f.put(kComposeColor,
        compose(contours ? *contours : Image(f.scene.width, f.scene.height, 1), interior ? *interior : Image(),
                paper_color ? *paper_color : Image(), f.params<ComposeParams>()));
});

}  // namespace plumbago::reference
