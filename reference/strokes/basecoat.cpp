// Base coat, CPU reference (Kalnins et al. 2002, §4.2; formula in common/strokes/basecoat.hpp).
#include "common/strokes/basecoat.hpp"

#include "reference/core/stage.hpp"
#include "reference/util/rows.hpp"
#include "reference/util/sampler.hpp"

namespace plumbago::reference {

namespace {

// The pixel's triangle record (s0, s1, s2, coated).
glm::vec4 triangle_record(const GBuffer& g, const TriangleShades& shades, int x, int y) {
  return shades.corners[shades.first_triangle[g.ids.at(x, y, 0) - 1] + g.ids.at(x, y, 1)];
}

// s at the pixel: the corners' s weighted by the barycentrics.
float interpolated_shade(const GBuffer& g, glm::vec4 corners, int x, int y) {
  return g.bary.at(x, y, 0) * corners[0] + g.bary.at(x, y, 1) * corners[1] + g.bary.at(x, y, 2) * corners[2];
}

// The coat T(s), straight alpha, on the stroke objects; transparent elsewhere.
Image coat(const GBuffer& g, const TriangleShades& shades, const Image& texture) {
  Image out(g.ids.width, g.ids.height, 4);
  const SamplerState linear_clamped;  // LINEAR, CLAMP_TO_EDGE
  for_each_row(out.height, [&](int y) {
    for (int x = 0; x < out.width; ++x) {
      if (g.background(x, y)) continue;
      glm::vec4 record = triangle_record(g, shades, x, y);
      glm::vec4 c = record.w * sample(texture, {interpolated_shade(g, record, x, y), 0.5f}, linear_clamped);
      for (int ch = 0; ch < 4; ++ch) out.at(x, y, ch) = c[ch];
    }
  });
  return out;
}

}  // namespace

PLUMBAGO_REFERENCE_STAGE(basecoat, [](ReferenceFrame& f) {
  auto p = f.params<BaseCoatParams>();
  f.put(kCoat, coat(f.get(kGBuffer), triangle_shades(f.ordinary, p), basecoat_texture(p)));
});

}  // namespace plumbago::reference
