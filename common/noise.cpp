#include "common/noise.hpp"

#include <algorithm>
#include <cmath>

#include "common/random.hpp"

namespace plumbago {

namespace {

int wrap(int i, int n) { return ((i % n) + n) % n; }

float fade(float t) { return t * t * t * (t * (t * 6 - 15) + 10); }  // Perlin 2002

}  // namespace

TileablePerlin::TileablePerlin(int period, uint32_t seed, const std::string& name) : period_(std::max(1, period)) {
  Rng rng(seed, name);
  gradients_.resize(size_t(period_) * period_);
  for (auto& g : gradients_) {
    double a = rng.uniform(0, 2 * M_PI);
    g = {float(std::cos(a)), float(std::sin(a))};
  }
}

glm::vec2 TileablePerlin::gradient(int i, int j) const {
  return gradients_[size_t(wrap(j, period_)) * period_ + size_t(wrap(i, period_))];
}

float TileablePerlin::operator()(glm::vec2 p) const {
  glm::vec2 cell = glm::floor(p), f = p - cell;
  int i = int(cell.x), j = int(cell.y);
  float n00 = glm::dot(gradient(i, j), f), n10 = glm::dot(gradient(i + 1, j), f - glm::vec2(1, 0));
  float n01 = glm::dot(gradient(i, j + 1), f - glm::vec2(0, 1)), n11 = glm::dot(gradient(i + 1, j + 1), f - glm::vec2(1, 1));
  float u = fade(f.x), v = fade(f.y);
  return glm::mix(glm::mix(n00, n10, u), glm::mix(n01, n11, u), v);
}

std::vector<TileablePerlin> fbm_octaves(int base_period, int octaves, uint32_t seed, const std::string& name) {
  std::vector<TileablePerlin> out;
  for (int o = 0; o < octaves; ++o) out.emplace_back(base_period << o, seed, name + "-octave-" + std::to_string(o));
  return out;
}

float fbm(const std::vector<TileablePerlin>& octaves, glm::vec2 uv) {
  float sum = 0, amplitude = 1;
  for (const auto& n : octaves) {
    sum += amplitude * n(uv * float(n.period()));
    amplitude *= 0.5f;
  }
  return sum;
}

TileableWorley::TileableWorley(int cells, uint32_t seed, const std::string& name) : cells_(std::max(1, cells)) {
  Rng rng(seed, name);
  points_.resize(size_t(cells_) * cells_);
  for (auto& p : points_) p = {float(rng.uniform()), float(rng.uniform())};
}

float TileableWorley::operator()(glm::vec2 uv) const {
  glm::vec2 p = uv * float(cells_), cell = glm::floor(p);
  float best = 2.0f;
  for (int dj = -1; dj <= 1; ++dj)
    for (int di = -1; di <= 1; ++di) {
      int i = int(cell.x) + di, j = int(cell.y) + dj;
      glm::vec2 feature = glm::vec2(i, j) + points_[size_t(wrap(j, cells_)) * cells_ + size_t(wrap(i, cells_))];
      best = std::min(best, glm::length(p - feature));
    }
  return best;
}

Image perlin_noise_texture(const NoiseTextureParams& p, uint32_t seed) {
  TileablePerlin noise(p.period, seed, "sketchy-noise");
  Image img(p.size, p.size, 1);
  float to_lattice = float(p.period) / float(p.size);
  for (int y = 0; y < p.size; ++y)
    for (int x = 0; x < p.size; ++x)
      img.at(x, y) = std::clamp(float(M_SQRT2) * noise(glm::vec2(float(x) + 0.5f, float(y) + 0.5f) * to_lattice), -1.0f, 1.0f);
  return img;
}

}  // namespace plumbago
