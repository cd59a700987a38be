// Composition and enhancement (Lee §6, Eq. 6).
//   D_i' = D_i (1 - a D_c)          interior strokes fade where contours are
//   I    = (1 - D_c)(1 - D_i')
//   I''  = mix(I, smoothstep(0, 1, I), contrast)    (Majumder & Gopi)
//   out  = I'' c_p                  c_p the paper color (white without paper)
#pragma once

#include "common/core/stage.hpp"
#include "common/pencil/multi_contour.hpp"
#include "common/pencil/pencil_interior.hpp"
#include "common/pencil/paper.hpp"

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
    StageDesc d{"compose", StageKind::Frame, "contours, interior and paper into the final image (SPEC 2.11)", {"compose"},
                {{kCopiesDarkness, when::effect_contours},
                 {kInteriorDarkness, when::effect_interior},
                 {kPaperColor, when::effect_paper},
                 {kOffsetGrids, when::effect_contours}},  // the GPU: the contours' reach bounds the pixels drawn
                {{kComposeColor, 3, Texel::Unorm8, "RGB", tolerance::kByte, "fed the same D_c, D_i and paper color; 8-bit target"}},
                {"contours", "interior", "crosshatch", "paper"}};
    d.outputs[0].frame_color = true;
    d.declared_effects = {{"contours", "image-space contours (Lee 2006 §4)"},
                          {"interior", "pencil textures along curvature directions (Lee 2006 §5)"},
                          {"crosshatch", "cross hatching in dark regions (Lee 2006 Fig. 7)"},
                          {"paper", "stroke/paper interaction and paper color (Lee 2006 §5.5)"}};
    return d;
  }
};

}  // namespace plumbago
