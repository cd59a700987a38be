#include "common/pencil_texture.hpp"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "common/random.hpp"

namespace plumbago {

namespace {

constexpr float kPi = 3.14159265358979f;

// A slightly curved line of graphite: chord from `start` in direction `dir`, bent
// sideways by bend * 4 t (1 - t) at fraction t of its length.
struct Stroke {
  glm::vec2 start, dir;
  float length, bend, pressure;
};

Stroke random_stroke(const PencilParams& p, Rng& rng) {
  float size = float(p.size);
  float angle = float(rng.uniform(-1, 1)) * p.angle_jitter_deg * kPi / 180;
  float length = p.stroke_length * size * float(rng.uniform(0.7, 1.3));
  return {{float(rng.uniform(0, size)), float(rng.uniform(0, size))},
          {std::cos(angle), std::sin(angle)},
          length,
          float(rng.uniform(-1, 1)) * p.stroke_bend * length,
          float(rng.uniform(0.6, 1.0))};
}

// Graphite grain: a fixed per-texel breakup of every stroke (lead catching the tooth of
// the paper), in [1 - grain, 1].
Image grain_field(const PencilParams& p, uint32_t seed) {
  Rng rng(seed, "pencil-grain");
  Image g(p.size, p.size, 1);
  for (float& v : g.data) v = 1.0f - p.grain * float(rng.uniform() * rng.uniform());
  return g;
}

// Darkness 1 - c_s the stroke leaves at a texel at distance `across` from its center
// line, `along` its chord: soft cross-section, tapered ends, grain.
float stroke_darkness(const Stroke& s, const PencilParams& p, float along, float across, float grain) {
  float t = along / s.length;
  if (t < 0 || t > 1) return 0;
  float taper = std::min(1.0f, std::min(t, 1 - t) * 8.0f);
  float profile = std::exp(-across * across / (0.25f * p.stroke_width * p.stroke_width));
  return s.pressure * taper * profile * grain;
}

int wrap(int i, int n) { return ((i % n) + n) % n; }

// Eq. 3-4 at every texel the stroke touches (the tile wraps); returns the change of the
// layer's sum of intensities.
double draw_stroke(const Stroke& s, const PencilParams& p, const Image& grain, Image& layer) {
  glm::vec2 normal(-s.dir.y, s.dir.x);
  float reach = std::abs(s.bend) + 2 * p.stroke_width;
  glm::vec2 a = s.start, b = s.start + s.dir * s.length;
  glm::ivec2 lo(glm::floor(glm::min(a, b) - reach)), hi(glm::ceil(glm::max(a, b) + reach));
  double change = 0;
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) {
      glm::vec2 d = glm::vec2(x + 0.5f, y + 0.5f) - s.start;
      float along = glm::dot(d, s.dir), t = along / s.length;
      float across = glm::dot(d, normal) - s.bend * 4 * t * (1 - t);
      int tx = wrap(x, p.size), ty = wrap(y, p.size);
      float dark = stroke_darkness(s, p, along, across, grain.at(tx, ty));
      if (dark <= 0) continue;
      float& c_t = layer.at(tx, ty);
      float c_a = c_t * dark;                 // c_a = c_t (1 - c_s)      (Eq. 3)
      if (c_t > p.white_level) c_a *= p.mu_w;  // white preservation       (Eq. 4)
      c_t -= p.mu_b * c_a;                     // c_t' = c_t - mu_b c_a    (Eq. 3)
      change -= p.mu_b * c_a;
    }
  return change;
}

}  // namespace

float layer_target(const PencilParams& p, int layer) {
  return 1.0f - float(layer) / float(p.layers - 1) * (1.0f - p.darkest);
}

std::vector<Image> pencil_layers(const PencilParams& p, uint32_t seed, int last) {
  Rng rng(seed, "pencil-strokes");
  Image grain = grain_field(p, seed);
  std::vector<Image> layers{Image(p.size, p.size, 1, 1.0f)};
  double texels = double(p.size) * p.size, sum = texels;
  int end = last < 0 ? p.layers : std::min(last + 1, p.layers);
  for (int l = 1; l < end; ++l) {
    Image next = layers.back();
    while (sum / texels > layer_target(p, l)) sum += draw_stroke(random_stroke(p, rng), p, grain, next);
    layers.push_back(std::move(next));
  }
  return layers;
}

}  // namespace plumbago
