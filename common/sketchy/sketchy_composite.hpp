// Sketchy composite and depth sprite (Nienhaus & Döllner §3.2-3.4, §4): the
// edge and shade maps read through the uncertainty's offsets, drawn as a depth sprite over
// what the pencil pipeline drew. The GPU tests the sprite against the G-buffer pass's depth
// buffer, which parity cannot upload: the composite's parity is over white paper, and the
// end-to-end comparison checks it over the pencil objects.
#pragma once

#include "common/sketchy/sketchy.hpp"
#include "common/core/stage.hpp"
#include "common/sketchy/sketchy_maps.hpp"
#include "common/sketchy/sketchy_enlarged.hpp"
#include "common/sketchy/sketchy_noise.hpp"
#include "common/pencil/compose.hpp"

namespace plumbago {

inline constexpr Buffer kSketchColor{"sketchy_composite.color"};
inline constexpr Buffer kSketchDepth{"sketchy_composite.depth"};

struct SketchyCompositeStage {
  using Params = TypeList<SketchyParams>;
  static bool object_style(const StageConfig& c) { return c.params.get<SketchyParams>().style == SketchyStyle::Object; }
  static StageDesc describe() {
    StageDesc d{"sketchy_composite", StageKind::Frame,
                "perturbed edges and shade, drawn as a depth sprite over the ordinary objects (SPEC 3.2-3.4)", {"sketchy"},
                {{kSketchyEdge}, {kSketchyShade}, {kSketchyGBuffer.depth}, {kSketchyNoise},
                 {kNoiseCoordinates, object_style}, {kComposeColor, when::pencil_effects, false},
                 {kGBuffer.depth, when::ordinary_drawn, false}},
                {{kSketchColor, 3, Texel::Unorm8, "the sketch over what the ordinary objects drew", tolerance::kByte,
                  "fed the same maps, sketchy G-buffer, noise and noise coordinates; 8-bit target"},
                 {kSketchDepth, 1, Texel::Float, "the sprite's normalized depth where the sketch was drawn, 1 elsewhere",
                  tolerance::kFloat, "fed the same maps, sketchy G-buffer, noise and noise coordinates; float target"}},
                {"sketchy"}};
    d.outputs[0].frame_color = true;
    d.outputs[0].draws_over = {kComposeColor.name};
    d.declared_effects = {{"sketchy", "sketchy drawing of the objects whose style is sketchy (Nienhaus & Doellner 2004); "
                                      "on by itself when one is", true}};
    return d;
  }
};

}  // namespace plumbago
