// Paper (Lee §5.5, Kalnins §4.4, Curtis et al. 1997): a tileable height field
// h in [0, 1] from Perlin fBm plus a Worley (cellular) component for fibres, its normal
// map n = normalize(-dh/dx s, -dh/dy s, 1) with s = bumpiness, and the paper color
// c_p = mix(color_valley, color_peak, h).
#pragma once

#include <cstdint>

#include "common/core/stage.hpp"
#include "common/util/image.hpp"

namespace plumbago {

struct PaperParams {
  static constexpr const char* stage = "paper";
  int size, base_period, octaves, worley_cells;
  float worley_weight, bumpiness, mu_p;
  float valley_r, valley_g, valley_b, peak_r, peak_g, peak_b;
  template <class V>
  void visit(V& v) {
    v.integer(size, "size", 512, 16, 4096, "width and height of the tileable paper, texels");
    v.integer(base_period, "base_period", 24, 1, 256, "Perlin lattice cells across the tile at the lowest octave");
    v.integer(octaves, "octaves", 5, 1, 10, "octaves of the fBm height");
    v.integer(worley_cells, "worley_cells", 48, 1, 1024, "Worley feature cells across the tile (fibre size)");
    v.real(worley_weight, "worley_weight", 0.5, 0.0, 1.0, "share of the cellular component in the height");
    v.real(bumpiness, "bumpiness", 8.0, 0.0, 1000.0, "s: slope scale of the normal map");
    v.real(mu_p, "mu_p", 0.05, 0.0, 0.5, "mu_p of Lee Eq. 5: how much the paper modulates strokes (paper: 0-0.1)");
    v.real(valley_r, "valley_r", 0.94, 0.0, 1.0, "paper color in the valleys, red");
    v.real(valley_g, "valley_g", 0.93, 0.0, 1.0, "paper color in the valleys, green");
    v.real(valley_b, "valley_b", 0.90, 0.0, 1.0, "paper color in the valleys, blue");
    v.real(peak_r, "peak_r", 1.0, 0.0, 1.0, "paper color on the peaks, red");
    v.real(peak_g, "peak_g", 1.0, 0.0, 1.0, "paper color on the peaks, green");
    v.real(peak_b, "peak_b", 0.98, 0.0, 1.0, "paper color on the peaks, blue");
  }
};

struct Paper {
  Image height;  // 1 ch, [0, 1]
  Image normal;  // 3 ch, unit
  Image color;   // 3 ch
};

Paper make_paper(const PaperParams& p, uint32_t seed);

inline constexpr Slot<Image> kPaperHeight{"paper.height"};
inline constexpr Slot<Image> kPaperNormal{"paper.normal"};
inline constexpr Slot<Image> kPaperColor{"paper.color"};

struct Scene;
struct Preprocessed;
struct PaperStage {
  using Params = TypeList<PaperParams>;
  static void make(const Scene& scene, Preprocessed& out);
  static StageDesc describe() {
    return {.name = "paper",
            .kind = StageKind::Preprocessing,
            .doc = "paper height, normal map and color (Lee et al. 2006, §5.5)",
            .params = {"paper"},
            .outputs = {{.handle = kPaperHeight, .texel = Texel::Host, .doc = "h in [0, 1]"},
                        {.handle = kPaperNormal, .channels = 3, .texel = Texel::Host, .doc = "unit normal map"},
                        {.handle = kPaperColor, .channels = 3, .texel = Texel::Host, .doc = "c_p"}},
            .preprocess = make};
  }
};

}  // namespace plumbago
