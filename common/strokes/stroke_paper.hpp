// The paper effect of stroke-based rendering (Kalnins et al. 2002 §4.4, after
// Curtis et al. 1997): a semi-transparent layer (the base coat, and later every stroke
// fragment) is composed onto the page through a transfer function of its alpha a set by
// the paper height h (the texture of Lee et al. 2006, §5.5, screen aligned, one texel per pixel, wrapping):
//   h' = sat(2 c (sat(2 b h) - 1/2) + 1/2)            brightness b, contrast c
//   a' = h' sat(2 a) + (1 - h') sat(2 a - 1)          peaks catch pigment, valleys resist
//   out = rgb a' + out (1 - a')                        premultiplied "over" (ONE, ONE_MINUS_SRC_ALPHA)
// With b = c = 1/2, h' = h and a' is the paper's t(a). The page is white.
//
// The stage draws the page of the objects whose style is `strokes` (Kalnins et al. 2002): at the
// pixels where the G-buffer shows one, and no sketchy sprite lies in front of it, the
// frame becomes the coat (with the base coat effect; else nothing) on the white page
// through the paper; every other pixel keeps what the other pipelines drew (white when
// none ran). Parity feeds no other pipeline's frame: there the others' pixels are white.
#pragma once

#include <algorithm>
#include <vector>

#include <glm/glm.hpp>

#include "common/scene/scene.hpp"

#include "common/core/stage.hpp"
#include "common/pencil/paper.hpp"
#include "common/sketchy/sketchy_composite.hpp"
#include "common/strokes/basecoat.hpp"

namespace plumbago {

struct StrokePaperParams {
  static constexpr const char* stage = "stroke_paper";
  float brightness, contrast;
  template <class V>
  void visit(V& v) {
    v.real(brightness, "brightness", 0.5, 0.0, 1.0,
           "b of Kalnins et al. 2002, §4.4: h' = sat(2c (sat(2b h) - 1/2) + "
           "1/2)");
    v.real(contrast, "contrast", 0.5, 0.0, 1.0,
           "c of Kalnins et al. 2002, §4.4 (b = c = 1/2: h' = h, the paper's t(a))");
  }
};

inline float saturate(float v) { return std::clamp(v, 0.0f, 1.0f); }

// h' of Kalnins et al. 2002, §4.4.
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

// Per object of `ordinary` (the G-buffer's objects): 1 when its style is strokes.
inline std::vector<uint32_t> stroke_object_flags(const Scene& ordinary) {
  std::vector<uint32_t> flags;
  for (const SceneObject& o : ordinary.objects) flags.push_back(o.style == Style::Strokes);
  return flags;
}

inline constexpr Buffer kPage{"stroke_paper.color"};

struct StrokePaperStage {
  using Params = TypeList<StrokePaperParams>;
  static StageDesc describe() {
    return {
        .name = "stroke_paper",
        .kind = StageKind::Frame,
        .doc = "the stroke objects' page: the base coat through the paper effect (Kalnins et al. 2002, §4.4)",
        .params = {"stroke_paper"},
        .inputs = {{.handle = kCoat, .used = when::effect_basecoat},
                   {.handle = kPaperHeight},
                   {.handle = kGBuffer.ids},
                   {.handle = kComposeColor, .used = when::pencil_effects, .fed_in_parity = false},
                   {.handle = kSketchColor, .used = when::effect_sketchy, .fed_in_parity = false},
                   {.handle = kSketchDepth, .used = when::effect_sketchy, .fed_in_parity = false}},
        .outputs = {{.handle = kPage,
                     .channels = 3,
                     .texel = Texel::Unorm8,
                     .doc = "the page with the coat over the stroke objects",
                     .tolerance = tolerance::kByte,
                     .tolerance_why = "fed the same coat and paper height; the GPU's coat is 8-bit: alpha off by half "
                                      "a step, doubled by the transfer's slope, plus half an output step: 1.5/255 at "
                                      "most (measured 1.05/255)",
                     .frame_color = true,
                     .draws_over = {kSketchColor.name, kComposeColor.name}}},
        .effects = {"strokes"},
        .declared_effects = {{"strokes",
                              "stroke-based rendering of the objects whose style is strokes (Kalnins et "
                              "al. 2002): paper, feature-line strokes; on by itself when one is",
                              true}}};
  }
};

}  // namespace plumbago
