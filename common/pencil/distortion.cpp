#include "common/pencil/distortion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/core/preprocess.hpp"
#include "common/util/random.hpp"

namespace plumbago {

namespace {

// Offsets of copy k at every grid vertex (Eq. 2).
Image distortion_grid(const ContourParams& p, int width, int height, Rng& rng) {
  int nx = (width + p.grid_cell - 1) / p.grid_cell + 1, ny = (height + p.grid_cell - 1) / p.grid_cell + 1;
  float b = 2.0f * std::numbers::pi_v<float> / p.shake_period;
  float phase_x = float(rng.uniform(0, 2 * std::numbers::pi)), phase_y = float(rng.uniform(0, 2 * std::numbers::pi));
  Image grid(nx, ny, 2);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      float x = float(i * p.grid_cell), y = float(j * p.grid_cell);
      float xi = float(rng.uniform(-1, 1)), eta = float(rng.uniform(-1, 1));
      grid.at(i, j, 0) = p.shake_amplitude * std::sin(b * y + phase_x) + p.shake_noise * xi;
      grid.at(i, j, 1) = p.shake_amplitude * std::sin(b * x + phase_y) + p.shake_noise * eta;
    }
  return grid;
}

}  // namespace

std::vector<Image> distortion_grids(const ContourParams& p, int width, int height, uint32_t seed) {
  std::vector<Image> grids;
  for (int k = 0; k < p.copies; ++k) {
    Rng rng(seed, "contour-distortion-" + std::to_string(k));
    grids.push_back(distortion_grid(p, width, height, rng));
  }
  return grids;
}

std::vector<glm::vec2> contour_texture_shifts(const ContourParams& p, uint32_t seed) {
  Rng rng(seed, "contour-texture-shift");
  std::vector<glm::vec2> shifts;
  for (int k = 0; k < p.copies; ++k) {
    float sx = float(rng.uniform(0, 4096)), sy = float(rng.uniform(0, 4096));
    shifts.push_back({sx, sy});
  }
  return shifts;
}

float largest_offset(const std::vector<Image>& grids) {
  float largest = 0;
  for (const Image& g : grids)
    for (float v : g.data) largest = std::max(largest, std::abs(v));
  return largest;
}

void DistortionStage::make(const Scene& scene, Preprocessed& out) {
  auto p = scene.params.get<ContourParams>();
  out.put(kOffsetGrids, distortion_grids(p, scene.width, scene.height, scene.seed));
  out.put(kTextureShifts, contour_texture_shifts(p, scene.seed));
}

}  // namespace plumbago
