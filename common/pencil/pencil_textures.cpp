#include "common/pencil/pencil_textures.hpp"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <numbers>
#include <stdexcept>
#include <string>

#include "common/core/preprocess.hpp"
#include "common/util/noise.hpp"
#include "common/util/progress.hpp"
#include "common/util/random.hpp"

namespace plumbago {

namespace {

constexpr int kFibrePeriod = 64;  // lattice of the fibre noise, in its own units

// A slightly curved line of graphite: chord from `start` in direction `dir`, bent
// sideways by bend * 4 t (1 - t) at fraction t of its length. Pressure goes linearly
// from pressure_start to pressure_end; `fibre` shifts the stroke into the fibre noise.
struct Stroke {
  glm::vec2 start, dir;
  float length, bend, pressure_start, pressure_end;
  glm::vec2 fibre;
};

Stroke random_stroke(const PencilTexturesParams& p, Rng& rng) {
  float size = float(p.size);
  float angle = float(rng.uniform(-1, 1)) * p.angle_jitter_deg * std::numbers::pi_v<float> / 180;
  float length = p.stroke_length * size * float(rng.uniform(0.7, 1.3));
  Stroke s;
  s.start = {float(rng.uniform(0, size)), float(rng.uniform(0, size))};
  s.dir = {std::cos(angle), std::sin(angle)};
  s.length = length;
  s.bend = float(rng.uniform(-1, 1)) * p.stroke_bend * length;
  s.pressure_start = float(rng.uniform(0.6, 1.0));
  s.pressure_end = float(rng.uniform(0.6, 1.0));
  s.fibre = {float(rng.uniform(0, kFibrePeriod)), float(rng.uniform(0, kFibrePeriod))};
  return s;
}

// Paper tooth: a fixed per-texel factor in [1 - tooth, 1], mostly near 1, low at a few
// texels that the lead skips over stroke after stroke (white specks in dark layers).
Image tooth_field(const PencilTexturesParams& p, uint32_t seed) {
  Rng rng(seed, "pencil-tooth");
  Image t(p.size, p.size, 1);
  for (float& v : t.data) {
    float u = float(rng.uniform());
    v = 1.0f - p.tooth * u * u * u;
  }
  return t;
}

// Graphite fibres: the ridges of the lead's tip leave fine streaks along a stroke.
// Gradient noise stretched along the stroke, in [1 - grain, 1].
struct Fibres {
  TileablePerlin noise;
  float grain, along_scale, across_scale;
  float operator()(const Stroke& s, float along, float across) const {
    float n = noise(s.fibre + glm::vec2(along / along_scale, across / across_scale));
    return 1.0f - grain * std::clamp(0.5f - 1.2f * n, 0.0f, 1.0f);
  }
};

// Darkness 1 - c_s the stroke leaves at distance `across` from its center line, at
// fraction t of its length: flat core with soft edges, tapered ends, pressure, fibres.
float stroke_darkness(const Stroke& s, const PencilTexturesParams& p, float t, float across, float fibre) {
  float half = 0.5f * p.stroke_width, edge = 0.6f;
  float profile = 1.0f - glm::smoothstep(half - edge, half + edge, std::abs(across));
  float taper = std::min(1.0f, std::min(t, 1 - t) * 10.0f);
  float pressure = glm::mix(s.pressure_start, s.pressure_end, t);
  return pressure * taper * profile * fibre;
}

int wrap(int i, int n) { return ((i % n) + n) % n; }

// Eq. 3-4 at every texel the stroke touches (the tile wraps); returns the change of the
// layer's sum of intensities.
double draw_stroke(const Stroke& s, const PencilTexturesParams& p, const Fibres& fibres, const Image& tooth,
                   Image& layer) {
  glm::vec2 normal(-s.dir.y, s.dir.x);
  float reach = std::abs(s.bend) + p.stroke_width + 1;
  glm::vec2 a = s.start, b = s.start + s.dir * s.length;
  glm::ivec2 lo(glm::floor(glm::min(a, b) - reach)), hi(glm::ceil(glm::max(a, b) + reach));
  double change = 0;
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) {
      glm::vec2 d = glm::vec2(x + 0.5f, y + 0.5f) - s.start;
      float along = glm::dot(d, s.dir), t = along / s.length;
      float across = glm::dot(d, normal) - s.bend * 4 * t * (1 - t);
      if (t < 0 || t > 1 || std::abs(across) > p.stroke_width) continue;
      int tx = wrap(x, p.size), ty = wrap(y, p.size);
      float dark = stroke_darkness(s, p, t, across, fibres(s, along, across)) * tooth.at(tx, ty);
      if (dark <= 0) continue;
      float& c_t = layer.at(tx, ty);
      float updated = graphite_update(p, c_t, 1 - dark);
      change += double(updated) - double(c_t);
      c_t = updated;
    }
  return change;
}

}  // namespace

float graphite_update(const PencilTexturesParams& p, float c_t, float c_s) {
  float c_a = c_t * (1 - c_s);             // c_a = c_t (1 - c_s)                       (Eq. 3)
  if (c_t > p.white_level) c_a *= p.mu_w;  // white enough: c_a = mu_w c_a              (Eq. 4)
  return c_t - p.mu_b * c_a;               // c_t' = c_t - mu_b c_a                     (Eq. 3)
}

float layer_target(const PencilTexturesParams& p, int layer) {
  return 1.0f - float(layer) / float(p.layers - 1) * (1.0f - p.darkest);
}

std::vector<Image> pencil_layers(const PencilTexturesParams& p, uint32_t seed, int last) {
  Rng rng(seed, "pencil-strokes");
  Fibres fibres{TileablePerlin(kFibrePeriod, seed, "pencil-fibres"), p.grain, p.fibre_length, p.fibre_width};
  Image tooth = tooth_field(p, seed);
  std::vector<Image> layers{Image(p.size, p.size, 1, 1.0f)};
  double texels = double(p.size) * p.size, sum = texels;
  // Strokes that cover the tile about once; a layer whose mean moves less than this
  // much per covering never reaches its target (mu_b 0, or a target near 0).
  long covering = std::max(1L, long(texels / (p.stroke_length * float(p.size) * p.stroke_width)));
  constexpr double kLeastProgress = 1e-6;
  int end = last < 0 ? p.layers : std::min(last + 1, p.layers);
  Progress progress("pencil textures (" + std::to_string(p.size) + "x" + std::to_string(p.size) + " layers)",
                    size_t(end - 1), true);
  for (int l = 1; l < end; ++l, progress.advance(1)) {
    Image next = layers.back();
    double before = sum;
    for (long n = 1; sum / texels > layer_target(p, l); ++n) {
      sum += draw_stroke(random_stroke(p, rng), p, fibres, tooth, next);
      if (n % covering != 0) continue;
      if ((before - sum) / texels < kLeastProgress)
        throw std::runtime_error("pencil layer " + std::to_string(l) + " cannot reach mean " +
                                 std::to_string(layer_target(p, l)) +
                                 ": raise pencil_textures.mu_b or pencil_textures.darkest");
      before = sum;
    }
    layers.push_back(std::move(next));
  }
  return layers;
}

void PencilTexturesStage::make(const Scene& scene, Preprocessed& out) {
  out.put(kPencilStack, pencil_layers(scene.params.get<PencilTexturesParams>(), scene.seed));
}

}  // namespace plumbago
