// The paper effect of stroke-based rendering (SPEC 4.2; Kalnins et al. 2002 §4.4, after
// Curtis et al. 1997): a semi-transparent layer (the base coat, and later every stroke
// fragment) is composed onto the page through a transfer function of its alpha a set by
// the paper height h (SPEC 1.3's texture, screen aligned, one texel per pixel, wrapping):
//   h' = sat(2 c (sat(2 b h) - 1/2) + 1/2)            brightness b, contrast c
//   a' = h' sat(2 a) + (1 - h') sat(2 a - 1)          peaks catch pigment, valleys resist
//   out = rgb a' + out (1 - a')                        premultiplied "over" (ONE, ONE_MINUS_SRC_ALPHA)
// With b = c = 1/2, h' = h and a' is the paper's t(a). The page is white.
#pragma once

#include <algorithm>

#include <glm/glm.hpp>

#include "common/stage.hpp"

namespace plumbago {

struct StrokePaperParams {
  static constexpr const char* stage = "stroke_paper";
  float brightness, contrast;
  template <class V>
  void visit(V& v) {
    v.real(brightness, "brightness", 0.5, 0.0, 1.0, "b of SPEC 4.2: h' = sat(2c (sat(2b h) - 1/2) + 1/2)");
    v.real(contrast, "contrast", 0.5, 0.0, 1.0, "c of SPEC 4.2 (b = c = 1/2: h' = h, the paper's t(a))");
  }
};

inline float saturate(float v) { return std::clamp(v, 0.0f, 1.0f); }

// h' of SPEC 4.2.
inline float adjusted_height(float h, const StrokePaperParams& p) {
  return saturate(2.0f * p.contrast * (saturate(2.0f * p.brightness * h) - 0.5f) + 0.5f);
}

// a' = h' sat(2a) + (1 - h') sat(2a - 1).
inline float paper_alpha(float a, float h_adjusted) {
  return h_adjusted * saturate(2.0f * a) + (1.0f - h_adjusted) * saturate(2.0f * a - 1.0f);
}

// `layer` (straight alpha) onto `under` through the paper at height h.
inline glm::vec3 over_paper(glm::vec4 layer, glm::vec3 under, float h, const StrokePaperParams& p) {
  float a = paper_alpha(layer.w, adjusted_height(h, p));
  return glm::vec3(layer) * a + under * (1.0f - a);
}

struct StrokePaperStage {
  using Params = TypeList<StrokePaperParams>;
  static StageDesc describe() {
    StageDesc d{"stroke_paper", StageKind::Frame, "the base coat onto the page through the paper effect (SPEC 4.2)",
                {"stroke_paper"}, {{"basecoat.coat"}, {"paper.height"}},
                {{"color", 3, Texel::Unorm8, "the page with the coat", tolerance::kByte,
                  "fed the same coat and paper height; the GPU's coat is 8-bit: alpha off by half a step, doubled by the "
                  "transfer's slope, plus half an output step: 1.5/255 at most (measured 1.05/255)"}},
                {"basecoat"}};
    d.outputs[0].frame_color = true;
    return d;
  }
};

}  // namespace plumbago
