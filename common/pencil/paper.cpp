#include "common/pencil/paper.hpp"

#include <algorithm>
#include <glm/glm.hpp>

#include "common/core/preprocess.hpp"
#include "common/util/noise.hpp"

namespace plumbago {

namespace {

// fBm plus fibres (1 - Worley distance), rescaled to [0, 1].
Image paper_height(const PaperParams& p, uint32_t seed) {
  auto octaves = fbm_octaves(p.base_period, p.octaves, seed, "paper-fbm");
  TileableWorley fibres(p.worley_cells, seed, "paper-worley");
  Image h(p.size, p.size, 1);
  for (int y = 0; y < p.size; ++y)
    for (int x = 0; x < p.size; ++x) {
      glm::vec2 uv((float(x) + 0.5f) / float(p.size), (float(y) + 0.5f) / float(p.size));
      h.at(x, y) = (1 - p.worley_weight) * fbm(octaves, uv) + p.worley_weight * (1 - fibres(uv));
    }
  auto [lo, hi] = std::minmax_element(h.data.begin(), h.data.end());
  float low = *lo, range = std::max(*hi - *lo, 1e-12f);
  for (float& v : h.data) v = (v - low) / range;
  return h;
}

// n = normalize(-dh/dx s, -dh/dy s, 1), periodic central differences in texels.
Image paper_normals(const Image& h, float s) {
  Image n(h.width, h.height, 3);
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x) {
      float dx = (h.at((x + 1) % h.width, y) - h.at((x + h.width - 1) % h.width, y)) * 0.5f;
      float dy = (h.at(x, (y + 1) % h.height) - h.at(x, (y + h.height - 1) % h.height)) * 0.5f;
      glm::vec3 v = glm::normalize(glm::vec3(-dx * s, -dy * s, 1.0f));
      for (int c = 0; c < 3; ++c) n.at(x, y, c) = v[c];
    }
  return n;
}

// c_p = mix(valley, peak, h)
Image paper_color(const Image& h, const PaperParams& p) {
  glm::vec3 valley(p.valley_r, p.valley_g, p.valley_b), peak(p.peak_r, p.peak_g, p.peak_b);
  Image c(h.width, h.height, 3);
  for (size_t i = 0; i < h.pixels(); ++i) {
    glm::vec3 v = glm::mix(valley, peak, h.data[i]);
    for (int k = 0; k < 3; ++k) c.data[i * 3 + k] = v[k];
  }
  return c;
}

}  // namespace

Paper make_paper(const PaperParams& p, uint32_t seed) {
  Paper paper;
  paper.height = paper_height(p, seed);
  paper.normal = paper_normals(paper.height, p.bumpiness);
  paper.color = paper_color(paper.height, p);
  return paper;
}

void PaperStage::make(const Scene& scene, Preprocessed& out) {
  Paper paper = make_paper(scene.params.get<PaperParams>(), scene.seed);
  out.put(kPaperHeight, std::move(paper.height));
  out.put(kPaperNormal, std::move(paper.normal));
  out.put(kPaperColor, std::move(paper.color));
}

}  // namespace plumbago
