#include "common/util/noise.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/util/random.hpp"

namespace plumbago {

namespace {

int wrap(int i, int n) { return ((i % n) + n) % n; }

float fade(float t) { return t * t * t * (t * (t * 6 - 15) + 10); }  // Perlin 2002

// 2/sqrt(3): 3D gradient noise with unit gradients lies within +-sqrt(3)/2.
constexpr float kUnitRange3 = 1.15470054f;

}  // namespace

TileablePerlin::TileablePerlin(int period, uint32_t seed, const std::string& name) : period_(std::max(1, period)) {
  Rng rng(seed, name);
  gradients_.resize(size_t(period_) * period_);
  for (auto& g : gradients_) {
    double a = rng.uniform(0, 2 * std::numbers::pi);
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
  float n01 = glm::dot(gradient(i, j + 1), f - glm::vec2(0, 1)),
        n11 = glm::dot(gradient(i + 1, j + 1), f - glm::vec2(1, 1));
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
      img.at(x, y) =
          std::clamp(float(M_SQRT2) * noise(glm::vec2(float(x) + 0.5f, float(y) + 0.5f) * to_lattice), -1.0f, 1.0f);
  return img;
}

TileablePerlin3::TileablePerlin3(int period, uint32_t seed, const std::string& name) : period_(std::max(1, period)) {
  Rng rng(seed, name);
  gradients_.resize(size_t(period_) * period_ * period_);
  for (auto& g : gradients_) {  // uniform on the sphere
    double z = rng.uniform(-1, 1), a = rng.uniform(0, 2 * std::numbers::pi), r = std::sqrt(1 - z * z);
    g = {float(r * std::cos(a)), float(r * std::sin(a)), float(z)};
  }
}

glm::vec3 TileablePerlin3::gradient(int i, int j, int k) const {
  size_t n = size_t(period_);
  return gradients_[(size_t(wrap(k, period_)) * n + size_t(wrap(j, period_))) * n + size_t(wrap(i, period_))];
}

float TileablePerlin3::operator()(glm::vec3 p) const {
  glm::vec3 cell = glm::floor(p), f = p - cell;
  glm::ivec3 c(cell);
  float corner[8];
  for (int n = 0; n < 8; ++n) {
    glm::ivec3 o(n & 1, (n >> 1) & 1, (n >> 2) & 1);
    corner[n] = glm::dot(gradient(c.x + o.x, c.y + o.y, c.z + o.z), f - glm::vec3(o));
  }
  float u = fade(f.x), v = fade(f.y), w = fade(f.z);
  float front = glm::mix(glm::mix(corner[0], corner[1], u), glm::mix(corner[2], corner[3], u), v);
  float back = glm::mix(glm::mix(corner[4], corner[5], u), glm::mix(corner[6], corner[7], u), v);
  return glm::mix(front, back, w);
}

std::vector<Image> perlin_noise_texture_3d(int size, int period, uint32_t seed) {
  TileablePerlin3 noise(period, seed, "sketchy-noise-3d");
  float to_lattice = float(period) / float(size);
  std::vector<Image> layers(size_t(size), Image(size, size, 1));
  for (int z = 0; z < size; ++z)
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        glm::vec3 p = (glm::vec3(x, y, z) + 0.5f) * to_lattice;
        layers[size_t(z)].at(x, y) = std::clamp(kUnitRange3 * noise(p), -1.0f, 1.0f);
      }
  return layers;
}

Image white_noise_texture(int size, uint32_t seed) {
  Rng rng(seed, "sketchy-white-noise");
  Image img(size, size, 2);
  for (float& v : img.data) v = float(rng.uniform());
  return img;
}

}  // namespace plumbago
