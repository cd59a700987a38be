#include "common/pencil/textures.hpp"

#include <cstdio>

#include "common/pencil/contour_texture.hpp"
#include "common/pencil/distortion.hpp"
#include "common/pencil/paper.hpp"
#include "common/pencil/pencil_textures.hpp"
#include "common/sketchy/sketchy.hpp"
#include "common/util/noise.hpp"

namespace plumbago {

Image contact_sheet(const std::vector<Image>& layers, int columns) {
  int s = layers.at(0).width, rows = (int(layers.size()) + columns - 1) / columns;
  Image sheet(columns * s, rows * s, 1, 1.0f);
  for (size_t l = 0; l < layers.size(); ++l) {
    int ox = int(l) % columns * s, oy = (rows - 1 - int(l) / columns) * s;  // row 0 of the image is the bottom
    for (int y = 0; y < s; ++y)
      for (int x = 0; x < s; ++x) sheet.at(ox + x, oy + y) = layers[l].at(x, y);
  }
  return sheet;
}

namespace {

// Two channels shown as red and green, x scale + bias (a PNG's second channel would be alpha).
Image rg_view(const Image& two, float scale, float bias) {
  Image v(two.width, two.height, 3);
  for (size_t i = 0; i < two.pixels(); ++i)
    for (int c = 0; c < 2; ++c) v.data[i * 3 + c] = two.data[i * 2 + c] * scale + bias;
  return v;
}

// Offsets (dx, dy) mapped from [-(a + r), a + r] to [0, 1] in red and green.
Image offset_view(const Image& grid, float bound) { return rg_view(grid, 1 / (2 * bound), 0.5f); }

// Signed values in [-1, 1] (normals, noise) mapped to [0, 1].
Image signed_view(const Image& n) {
  Image v = n;
  for (float& x : v.data) x = x * 0.5f + 0.5f;
  return v;
}

}  // namespace

std::map<std::string, Image> texture_gallery(const ParamSet& params, uint32_t seed, int width, int height) {
  std::map<std::string, Image> out;
  auto pencil = params.get<PencilTexturesParams>();
  auto contour = params.get<ContourParams>();
  std::vector<Image> layers = pencil_layers(pencil, seed);
  char name[64];
  for (size_t l = 0; l < layers.size(); ++l) {
    std::snprintf(name, sizeof name, "pencil_layer_%02zu", l);
    out[name] = layers[l];
  }
  out["pencil_contact_sheet"] = contact_sheet(layers, 8);
  out["contour_texture"] = layers.at(size_t(ContourTextureStage::layer(params)));
  Paper paper = make_paper(params.get<PaperParams>(), seed);
  out["paper_height"] = paper.height;
  out["paper_normal"] = signed_view(paper.normal);
  out["paper_color"] = paper.color;
  auto grids = distortion_grids(contour, width, height, seed);
  for (size_t k = 0; k < grids.size(); ++k)
    out["contour_offsets_" + std::to_string(k)] = offset_view(grids[k], contour.shake_amplitude + contour.shake_noise);
  auto noise = params.get<NoiseTextureParams>();
  auto sketchy = params.get<SketchyParams>();
  // What each sketchy style reads (Nienhaus & Döllner 2004, §3.2; §3.4, §4): Perlin (default, repeat), white noise
  // (rough; (u, v) + 0.5 in red and green), the 3D Perlin's first slice (object).
  out["sketchy_noise"] = signed_view(perlin_noise_texture(noise, seed));
  out["sketchy_white_noise"] = rg_view(white_noise_texture(noise.size, seed), 1, 0);
  out["sketchy_noise_3d_slice0"] =
      signed_view(perlin_noise_texture_3d(sketchy.noise3d_size, sketchy.noise3d_period, seed).front());
  return out;
}

}  // namespace plumbago
