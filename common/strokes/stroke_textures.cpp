#include "common/strokes/stroke_textures.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "common/util/random.hpp"

namespace plumbago {

namespace {

double smoothstep(double e0, double e1, double x) {
  double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

double quintic(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }  // Perlin 2002

// Smooth value noise in [0, 1): uniform random values on a lattice of cells_u x cells_v
// cells over the texture (cells_v + 1 rows of values, so v does not wrap), quintic
// interpolation between them; column cells_u is column 0, so it tiles in u.
class ValueNoise {
 public:
  ValueNoise(int cells_u, int cells_v, uint32_t seed, const std::string& name)
      : cells_u_(cells_u), cells_v_(cells_v), values_(size_t(cells_u) * size_t(cells_v + 1)) {
    Rng rng(seed, name);
    for (double& value : values_) value = rng.uniform();
  }

  double operator()(double u, double v) const {
    double x = u * cells_u_, y = std::clamp(v, 0.0, 1.0) * cells_v_;
    int i = int(std::floor(x)), j = std::min(int(std::floor(y)), cells_v_ - 1);
    double fx = quintic(x - i), fy = quintic(y - j);
    double bottom = std::lerp(at(i, j), at(i + 1, j), fx), top = std::lerp(at(i, j + 1), at(i + 1, j + 1), fx);
    return std::lerp(bottom, top, fy);
  }

 private:
  double at(int i, int j) const {
    int wrapped = ((i % cells_u_) + cells_u_) % cells_u_;
    return values_[size_t(j) * size_t(cells_u_) + size_t(wrapped)];
  }
  int cells_u_, cells_v_;
  std::vector<double> values_;
};

// c(v) = smoothstep(0, e, v) smoothstep(0, e, 1 - v), e the share of the width that fades.
double cross_section(double edge, double v) { return smoothstep(0, edge, v) * smoothstep(0, edge, 1 - v); }

std::string layer_name(StrokeTextureKind kind, const char* layer) {
  return "stroke-texture-" + stroke_texture_names()[size_t(kind)] + "-" + layer;
}

// A grain g(u, v) and the share e of the width its cross-section fades over.
struct Recipe {
  double edge;
  std::function<double(double, double)> grain;
};

// Streaks along u (about 40 texels long, 1/14 of the width across) over a fine grain.
Recipe pencil(uint32_t seed) {
  ValueNoise streaks(6, 14, seed, layer_name(StrokeTextureKind::Pencil, "streaks"));
  ValueNoise grain(128, 16, seed, layer_name(StrokeTextureKind::Pencil, "grain"));
  return {0.25, [=](double u, double v) { return 0.25 + 0.7 * streaks(u, v) + 0.3 * (grain(u, v) - 0.5); }};
}

// Coarse blotches that break the stroke where the blotch noise is low, over a coarse grain.
Recipe charcoal(uint32_t seed) {
  ValueNoise blotches(5, 2, seed, layer_name(StrokeTextureKind::Charcoal, "blotches"));
  ValueNoise grain(80, 12, seed, layer_name(StrokeTextureKind::Charcoal, "grain"));
  return {0.3, [=](double u, double v) {
            double breaks = smoothstep(0.3, 0.6, blotches(u, v));
            return breaks * (0.15 + smoothstep(0.2, 0.8, grain(u, v)));
          }};
}

// Nearly solid: a faint streak.
Recipe ink(uint32_t seed) {
  ValueNoise streaks(4, 8, seed, layer_name(StrokeTextureKind::Ink, "streaks"));
  return {0.15, [=](double u, double v) { return 0.9 + 0.1 * streaks(u, v); }};
}

Recipe recipe(StrokeTextureKind kind, uint32_t seed) {
  switch (kind) {
    case StrokeTextureKind::Pencil:
      return pencil(seed);
    case StrokeTextureKind::Charcoal:
      return charcoal(seed);
    case StrokeTextureKind::Ink:
      return ink(seed);
  }
  throw std::invalid_argument("stroke_texture: unknown kind " + std::to_string(int(kind)));
}

}  // namespace

const std::vector<std::string>& stroke_texture_names() {
  static const std::vector<std::string> names = {"pencil", "charcoal", "ink"};
  return names;
}

Image stroke_texture(StrokeTextureKind kind, uint32_t seed) {
  Recipe r = recipe(kind, seed);
  Image img(kStrokeTextureWidth, kStrokeTextureHeight, 1);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      double u = (x + 0.5) / img.width, v = (y + 0.5) / img.height;
      img.at(x, y) = float(std::clamp(r.grain(u, v), 0.0, 1.0) * cross_section(r.edge, v));
    }
  return img;
}

}  // namespace plumbago
