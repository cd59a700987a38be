#include "reference/pencil/pencil_interior.hpp"

#include <algorithm>
#include <cmath>

#include "reference/core/stage.hpp"
#include "reference/util/rows.hpp"
#include "reference/util/sampler.hpp"

namespace plumbago::reference {

namespace {

const SamplerState kStack{Filter::Linear, Wrap::Repeat, Wrap::Repeat, Wrap::ClampToEdge};

struct Corners {
  glm::vec3 w, theta;
};

glm::vec3 texel_wrapped(const Image& img, int x, int y) {
  int tx = ((x % img.width) + img.width) % img.width, ty = ((y % img.height) + img.height) % img.height;
  return {img.at(tx, ty, 0), img.at(tx, ty, 1), img.at(tx, ty, 2)};
}

// c_k = P(R(-theta) p / texture_scale, r), then the paper effect c_k' (2.7, 2.10).
float corner_sample(const std::vector<Image>& stack, glm::vec2 p, float theta, float r, const glm::vec3* paper_normal,
                    const InteriorParams& ip, float mu_p) {
  float c = std::cos(theta), s = std::sin(theta);
  glm::vec2 uv = glm::vec2(c * p.x + s * p.y, -s * p.x + c * p.y) / ip.texture_scale;  // R(-theta) p
  float tone = sample(stack, glm::vec3(uv / float(stack[0].width), r), kStack).x;
  if (!paper_normal) return tone;
  return std::clamp(tone + mu_p * glm::dot(glm::vec3(c, s, 0.0f), *paper_normal), 0.0f, 1.0f);
}

// c = w0 c_0' + w1 c_1' + w2 c_2' (2.8), corners of weight 0 not sampled.
float blended(const std::vector<Image>& stack, glm::vec2 p, const Corners& k, float r, const glm::vec3* n,
              const InteriorParams& ip, float mu_p) {
  glm::vec3 w = blend_weights(k.w, ip);
  float c = 0;
  for (int i = 0; i < 3; ++i)
    if (w[i] != 0.0f) c += w[i] * corner_sample(stack, p, k.theta[i], r, n, ip, mu_p);
  return c;
}

float smoothstep(float e0, float e1, float x) {
  float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3 - 2 * t);
}

}  // namespace

Image interior_darkness(const GBuffer& g, const Image& intensity, const std::vector<Image>& stack,
                        const Image& paper_normal, const InteriorOptions& o, const InteriorParams& ip, float mu_p) {
  Image out(g.depth.width, g.depth.height, 1);
  float layers = float(stack.size());
  for_each_row(out.height, [&](int y) {
    for (int x = 0; x < out.width; ++x) {
      if (g.background(x, y)) continue;
      float i = intensity.at(x, y);
      float r = ((1.0f - i) * (layers - 1.0f) + 0.5f) / layers;  // tone to layer (2.6)
      glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
      glm::vec3 w(g.bary.at(x, y, 0), g.bary.at(x, y, 1), g.bary.at(x, y, 2));
      glm::vec3 n = o.paper ? texel_wrapped(paper_normal, x, y) : glm::vec3(0);
      const glm::vec3* np = o.paper ? &n : nullptr;
      glm::vec3 t_min(g.theta_min.at(x, y, 0), g.theta_min.at(x, y, 1), g.theta_min.at(x, y, 2));
      float c = blended(stack, p, {w, t_min}, r, np, ip, mu_p);
      float h = o.crosshatch ? 1.0f - smoothstep(ip.crosshatch_below - ip.crosshatch_band, ip.crosshatch_below, i) : 0;
      if (h > 0) {  // cross hatching (2.9)
        glm::vec3 t_max(g.theta_max.at(x, y, 0), g.theta_max.at(x, y, 1), g.theta_max.at(x, y, 2));
        c *= 1.0f + (blended(stack, p, {w, t_max}, r, np, ip, mu_p) - 1.0f) * h;
      }
      out.at(x, y) = 1.0f - c;
    }
  });
  return out;
}

PLUMBAGO_REFERENCE_STAGE(pencil_interior, [](ReferenceFrame& f) {
  const Image* paper_normal = f.get(maybe(kPaperNormal));
  f.put(kInteriorDarkness, interior_darkness(f.get(kGBuffer), f.get(kIntensity), f.get(kPencilStack),
                                             paper_normal ? *paper_normal : Image(), interior_options(f.scene.effects),
                                             f.params<InteriorParams>(), f.params<PaperParams>().mu_p));
});

}  // namespace plumbago::reference
