// Base coat (Kalnins et al. 2002 §4.2, toon shading after Lake et al. 2000): the
// first layer of stroke-based rendering. Per vertex, from the shading normal n and the
// scene's unit lights L_k (world space, intensities I_k),
//   s = sum_k I_k (n . L_k)          (|n . L_k| with abs_n_dot_l)
// interpolated across the face with the barycentrics, looks up a 1D RGBA texture T at
// texture coordinate s (LINEAR, CLAMP_TO_EDGE: s <= 0 reads the first texel): the coat is
// T(s), straight alpha, on the objects whose style is `strokes` and transparent (0)
// elsewhere. The paper effect of Kalnins et al. 2002, §4.4
// (common/strokes/stroke_paper.hpp) composes it. T is generated here from a preset: `toon`, two tones split at
// `threshold`; `smooth`, a linear ramp from the dark to the light color; `solid`, the light color alone.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "common/core/stage.hpp"
#include "common/scene/gbuffer.hpp"
#include "common/scene/scene.hpp"
#include "common/util/image.hpp"

namespace plumbago {

enum class BaseCoatPreset { Toon, Smooth, Solid };

struct BaseCoatParams {
  static constexpr const char* stage = "basecoat";
  BaseCoatPreset preset;
  bool abs_n_dot_l;
  float threshold;
  float dark_r, dark_g, dark_b, dark_a, light_r, light_g, light_b, light_a;
  template <class V>
  void visit(V& v) {
    v.choice(preset, "preset", BaseCoatPreset::Toon, {"toon", "smooth", "solid"},
             "the 1D texture: two tones (toon), a ramp from dark to light (smooth), or the light color (solid)");
    v.boolean(abs_n_dot_l, "abs_n_dot_l", false, "s sums |n.L| instead of n.L (Kalnins et al. 2002, §4.2)");
    v.real(threshold, "threshold", 0.4, 0.0, 1.0, "toon: s below this gets the dark tone");
    v.real(dark_r, "dark_r", 0.55, 0.0, 1.0, "dark tone, red");
    v.real(dark_g, "dark_g", 0.45, 0.0, 1.0, "dark tone, green");
    v.real(dark_b, "dark_b", 0.35, 0.0, 1.0, "dark tone, blue");
    v.real(dark_a, "dark_a", 1.0, 0.0, 1.0, "dark tone, alpha (below 1 the paper shows through)");
    v.real(light_r, "light_r", 0.93, 0.0, 1.0, "light tone, red");
    v.real(light_g, "light_g", 0.85, 0.0, 1.0, "light tone, green");
    v.real(light_b, "light_b", 0.70, 0.0, 1.0, "light tone, blue");
    v.real(light_a, "light_a", 1.0, 0.0, 1.0, "light tone, alpha");
  }
};

constexpr int kBaseCoatTexels = 256;  // the 1D texture's width

// T: kBaseCoatTexels x 1, RGBA, straight alpha.
Image basecoat_texture(const BaseCoatParams& p);

// s at each corner of each triangle, the objects' records one after the other
// ((s0, s1, s2, coated) per triangle, coated = 1 on a `strokes` object and 0 on others;
// first_triangle[o] is object o's first), from the world geometry both backends draw
// (common/scene/gbuffer.hpp world_geometry). The coat is T(s) coated.
struct TriangleShades {
  std::vector<glm::vec4> corners;
  std::vector<uint32_t> first_triangle;
};
TriangleShades triangle_shades(const Scene& scene, const BaseCoatParams& p);

inline constexpr Buffer kCoat{"basecoat.coat"};

struct BaseCoatStage {
  using Params = TypeList<BaseCoatParams>;
  static StageDesc describe() {
    return {.name = "basecoat",
            .kind = StageKind::Frame,
            .doc = "toon or solid base coat from a 1D texture (Kalnins et al. 2002, §4.2)",
            .params = {"basecoat"},
            .inputs = {{.handle = kGBuffer.ids}, {.handle = kGBuffer.bary}},
            .outputs = {{.handle = kCoat,
                         .channels = 4,
                         .texel = Texel::Unorm8,
                         .doc = "T(s), straight alpha, on the stroke objects; 0 elsewhere",
                         .tolerance = tolerance::kByte,
                         .tolerance_why = "fed the same G-buffer and per-vertex s; bilinear lookup of the 1D texture; "
                                          "8-bit target"}},
            .effects = {"basecoat"},
            .declared_effects = {{"basecoat",
                                  "the base coat of the objects whose style is strokes (Kalnins 2002 §4.2), "
                                  "through the paper effect (§4.4); on by default for them",
                                  true}}};
  }
};

}  // namespace plumbago
