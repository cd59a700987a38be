#include "reference/pencil/multi_contour.hpp"

#include "reference/util/sampler.hpp"

#include "reference/core/stage.hpp"
#include "reference/util/rows.hpp"

namespace plumbago::reference {

namespace {

const SamplerState kClamp{Filter::Linear, Wrap::ClampToEdge, Wrap::ClampToEdge};
const SamplerState kRepeat{Filter::Linear, Wrap::Repeat, Wrap::Repeat};

// offset_k(p): the grid vertex (i, j) sits at window position (i, j) * grid_cell, i.e.
// at texel center i + 1/2 of the grid texture; the texture's bilinear filter interpolates
// a cell's four corners (Lee et al. 2006, §4.2, Eq. 2).
glm::vec2 offset_at(const Image& grid, glm::vec2 p, float cell) {
  glm::vec2 st = (p / cell + 0.5f) / glm::vec2(grid.width, grid.height);
  return glm::vec2(sample(grid, st, kClamp));
}

// One copy's darkness, alpha d_k mix(1, t_k, strength).
float copy_darkness(const Image& lit, const Image& grid, const Image& tex, glm::vec2 shift, glm::vec2 p,
                    const ContourParams& c) {
  glm::vec2 window(lit.width, lit.height);
  float d_k = sample(lit, (p + offset_at(grid, p, float(c.grid_cell))) / window, kClamp).x;
  float t_k = 1.0f - sample(tex, (p / c.texture_scale + shift) / glm::vec2(tex.width, tex.height), kRepeat).x;
  return c.stroke_opacity * d_k * (1.0f + (t_k - 1.0f) * c.texture_strength);
}

}  // namespace

Image multi_contour_darkness(const Image& lit, const std::vector<Image>& grids, const Image& tex,
                             const std::vector<glm::vec2>& shifts, const ContourParams& p) {
  Image out(lit.width, lit.height, 1);
  for_each_row(lit.height, [&](int y) {
    for (int x = 0; x < lit.width; ++x) {
      glm::vec2 center(float(x) + 0.5f, float(y) + 0.5f);
      float untouched = 1.0f;  // prod_k (1 - alpha d_k ...)
      for (size_t k = 0; k < grids.size(); ++k)
        untouched *= 1.0f - copy_darkness(lit, grids[k], tex, shifts[k], center, p);
      out.at(x, y) = 1.0f - untouched;
    }
  });
  return out;
}

PLUMBAGO_REFERENCE_STAGE(multi_contour, [](ReferenceFrame& f) {
  f.put(kCopiesDarkness, multi_contour_darkness(f.get(kLitContourDarkness), f.get(kOffsetGrids), f.get(kContourTexture),
                                                f.get(kTextureShifts), f.params<ContourParams>()));
});

}  // namespace plumbago::reference
