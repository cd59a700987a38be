// Tileable noise on [0, period)^2 lattices: Perlin gradient noise, its fBm, and Worley
// (cellular) noise. Everything wraps with the given integer period, so textures made
// from them tile without a seam. Deterministic in (seed, name).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/util/image.hpp"

namespace plumbago {

class TileablePerlin {
 public:
  // Unit gradients on a period x period lattice.
  TileablePerlin(int period, uint32_t seed, const std::string& name);
  // Gradient noise at p (lattice units), in [-sqrt(1/2), sqrt(1/2)], 0 at lattice
  // points; wraps every `period`.
  float operator()(glm::vec2 p) const;
  int period() const { return period_; }

 private:
  glm::vec2 gradient(int i, int j) const;
  int period_;
  std::vector<glm::vec2> gradients_;
};

// Fractal sum of `octaves` Perlin noises, frequencies base x 2^o, amplitudes 2^-o.
// u, v in [0, 1) over the tile.
float fbm(const std::vector<TileablePerlin>& octaves, glm::vec2 uv);
std::vector<TileablePerlin> fbm_octaves(int base_period, int octaves, uint32_t seed, const std::string& name);

class TileableWorley {
 public:
  TileableWorley(int cells, uint32_t seed, const std::string& name);
  // Distance to the nearest feature point, in cell units (0 at a point, ~1 far away);
  // uv in [0, 1) over the tile.
  float operator()(glm::vec2 uv) const;

 private:
  int cells_;
  std::vector<glm::vec2> points_;  // one per cell, in cell-local [0,1)^2
};

// Tileable 3D Perlin gradient noise on a period^3 lattice (the `object` style's 3D
// noise texture, Nienhaus & Döllner §4.3).
class TileablePerlin3 {
 public:
  TileablePerlin3(int period, uint32_t seed, const std::string& name);
  // Gradient noise at p (lattice units), 0 at lattice points; wraps every `period`.
  float operator()(glm::vec3 p) const;

 private:
  glm::vec3 gradient(int i, int j, int k) const;
  int period_;
  std::vector<glm::vec3> gradients_;
};

// size^3 texels as `size` layers, TileablePerlin3 with `period` cells across, scaled to
// [-1, 1] and sampled at texel centers (sketchy.noise3d_size, sketchy.noise3d_period).
std::vector<Image> perlin_noise_texture_3d(int size, int period, uint32_t seed);

// size x size, 2 channels of independent uniform values in [0, 1): the uncorrelated
// offsets of the `rough` style (Nienhaus & Döllner 2004, §3.4, §4), read with nearest filtering.
Image white_noise_texture(int size, uint32_t seed);

// The noise texture sketchy drawing turns into turbulence (Nienhaus & Döllner
// 2004 §3.2): one octave of tileable Perlin noise; the octaves of the turbulence are
// this texture sampled at 2^i times the frequency with GL_REPEAT.
struct NoiseTextureParams {
  static constexpr const char* stage = "noise";
  int size, period;
  template <class V>
  void visit(V& v) {
    v.integer(size, "size", 256, 8, 4096, "width and height of the tileable Perlin noise texture, texels");
    v.integer(period, "period", 8, 1, 1024, "Perlin lattice cells across the texture (features of size/period texels)");
  }
};

// size x size, 1 channel, Perlin noise scaled to [-1, 1], sampled at texel centers.
Image perlin_noise_texture(const NoiseTextureParams& p, uint32_t seed);

}  // namespace plumbago
