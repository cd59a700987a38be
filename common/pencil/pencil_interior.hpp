// Interior pencil shading (Lee §5, Pacheco §7-8), one function of the
// G-buffer per pixel:
//   s = (1 - I') (layers - 1), r = (s + 0.5) / layers                     tone to layer (2.6)
//   c_k = P(R(-theta_k) p / texture_scale, r)                              texture rotation (2.7)
//   c_k' = clamp(c_k + mu_p ((cos theta_k, sin theta_k, 0) . n_paper(p)))  paper effect (2.10)
//   c = w0 c_0' + w1 c_1' + w2 c_2'                                        3-way blending (2.8)
//   c = c mix(1, c_max, h), h = 1 - smoothstep(T - band, T, I')           cross hatching (2.9)
//   interior darkness D_i = 1 - c; 0 on the background
// P is the pencil stack as a 3D texture (LINEAR; REPEAT in s and t, CLAMP_TO_EDGE in r),
// p the pixel center (texture origin p0 = 0). n_paper and the paper color are read
// texel for pixel (texelFetch, wrapping), so they need no filtering.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "common/core/stage.hpp"
#include "common/pencil/interior_intensity.hpp"
#include "common/pencil/paper.hpp"
#include "common/pencil/pencil_textures.hpp"
#include "common/scene/gbuffer.hpp"

namespace plumbago {

// Which optional parts of the interior a scene's effects ask for.
struct InteriorOptions {
  bool crosshatch = false;  // effect "crosshatch": the max-curvature directions are sampled
  bool paper = false;       // effect "paper": stroke/paper interaction and paper color
};

inline InteriorOptions interior_options(const std::vector<std::string>& effects) {
  auto has = [&](const char* e) { return std::find(effects.begin(), effects.end(), e) != effects.end(); };
  return {has("crosshatch"), has("paper")};
}

// The weights of the corners' textures (Lee et al. 2006, §5.4): the barycentrics `w` for three-way
// blending; for nearest_corner, 1 for the largest of them (the first on a tie), 0 else.
glm::vec3 blend_weights(glm::vec3 w, const InteriorParams& p);

inline constexpr Buffer kInteriorDarkness{"pencil_interior.interior_darkness"};  // D_i

struct PencilInteriorStage {
  using Params = TypeList<>;
  static StageDesc describe() {
    return {.name = "pencil_interior",
            .kind = StageKind::Frame,
            .doc =
                "tone to layer, rotated pencil textures, 3-way blending, cross hatching, paper effect "
                "(Lee et al. 2006, §5.1-5.5)",
            .params = {"interior", "paper"},
            .inputs = {{.handle = kIntensity},
                       {.handle = kGBuffer.ids},
                       {.handle = kGBuffer.bary},
                       {.handle = kGBuffer.theta_min},
                       {.handle = kGBuffer.theta_max},
                       {.handle = kPencilStack},
                       {.handle = kPaperNormal, .used = when::effect_paper}},
            .outputs = {{.handle = kInteriorDarkness,
                         .doc = "D_i; 0 on the background",
                         .tolerance = tolerance::kSampled,
                         .tolerance_why = "fed the same G-buffer (the GPU its corner angles as triangle records), I', "
                                          "pencil stack and paper"}}};
  }
};

}  // namespace plumbago
