// Composition and enhancement (Lee §6, Eq. 6).
//   D_i' = D_i (1 - a D_c)          interior strokes fade where contours are
//   I    = (1 - D_c)(1 - D_i')
//   I''  = mix(I, smoothstep(0, 1, I), contrast)    (Majumder & Gopi)
//   out  = I'' c_p                  c_p the paper color (white without paper)
#pragma once

#include "common/core/stage.hpp"
#include "common/pencil/multi_contour.hpp"
#include "common/pencil/paper.hpp"
#include "common/pencil/pencil_interior.hpp"

namespace plumbago {

struct ComposeParams {
  static constexpr const char* stage = "compose";
  float contour_attenuation, contrast;
  template <class V>
  void visit(V& v) {
    v.real(contour_attenuation, "contour_attenuation", 0.5, 0.0, 1.0,
           "a: how much contours fade the interior strokes under them (Lee et al. 2006, §6, Eq. 6)");
    v.real(contrast, "contrast", 0.5, 0.0, 1.0, "weight of the smoothstep contrast enhancement (Lee §6)");
  }
};

inline constexpr Buffer kComposeColor{"compose.color"};

struct ComposeStage {
  using Params = TypeList<ComposeParams>;
  static StageDesc describe() {
    return {.name = "compose",
            .kind = StageKind::Frame,
            .doc = "contours, interior and paper into the final image (Lee et al. 2006, §6, Eq. 6)",
            .params = {"compose"},
            .inputs = {{.handle = kCopiesDarkness, .used = when::effect_contours},
                       {.handle = kInteriorDarkness, .used = when::effect_interior},
                       {.handle = kPaperColor, .used = when::effect_paper},
                       // the GPU: the contours' reach bounds the pixels drawn
                       {.handle = kOffsetGrids, .used = when::effect_contours}},
            .outputs = {{.handle = kComposeColor,
                         .channels = 3,
                         .texel = Texel::Unorm8,
                         .doc = "RGB",
                         .tolerance = tolerance::kByte,
                         .tolerance_why = "fed the same D_c, D_i and paper color; 8-bit target",
                         .frame_color = true}},
            .effects = {"contours", "interior", "crosshatch", "paper"},
            .declared_effects = {{"contours", "image-space contours (Lee 2006 §4)"},
                                 {"interior", "pencil textures along curvature directions (Lee 2006 §5)"},
                                 {"crosshatch", "cross hatching in dark regions (Lee 2006 Fig. 7)"},
                                 {"paper", "stroke/paper interaction and paper color (Lee 2006 §5.5)"}}};
  }
};

}  // namespace plumbago
