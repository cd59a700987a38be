// Sketchy composite and depth sprite (Nienhaus & Döllner §3.2-3.4, §4): the
// edge and shade maps read through the uncertainty's offsets, drawn as a depth sprite over
// what the pencil pipeline drew. The GPU tests the sprite against the G-buffer pass's depth
// buffer, which parity cannot upload: the composite's parity is over white paper, and the
// end-to-end comparison checks it over the pencil objects.
#pragma once

#include "common/core/stage.hpp"
#include "common/pencil/compose.hpp"
#include "common/sketchy/sketchy.hpp"
#include "common/sketchy/sketchy_enlarged.hpp"
#include "common/sketchy/sketchy_maps.hpp"
#include "common/sketchy/sketchy_noise.hpp"

namespace plumbago {

inline constexpr Buffer kSketchColor{"sketchy_composite.color"};
inline constexpr Buffer kSketchDepth{"sketchy_composite.depth"};

struct SketchyCompositeStage {
  using Params = TypeList<SketchyParams>;
  static bool object_style(const StageConfig& c) { return c.params.get<SketchyParams>().style == SketchyStyle::Object; }
  static StageDesc describe() {
    const char* fed = "fed the same maps, sketchy G-buffer, noise and noise coordinates";
    return {.name = "sketchy_composite",
            .kind = StageKind::Frame,
            .doc =
                "perturbed edges and shade, drawn as a depth sprite over the ordinary objects "
                "(Nienhaus & Döllner 2004, §3.2-3.3)",
            .params = {"sketchy"},
            .inputs = {{.handle = kSketchyEdge},
                       {.handle = kSketchyShade},
                       {.handle = kSketchyGBuffer.depth},
                       {.handle = kSketchyNoise},
                       {.handle = kNoiseCoordinates, .used = object_style},
                       {.handle = kComposeColor, .used = when::pencil_effects, .fed_in_parity = false},
                       {.handle = kGBuffer.depth, .used = when::ordinary_drawn, .fed_in_parity = false}},
            .outputs = {{.handle = kSketchColor,
                         .channels = 3,
                         .texel = Texel::Unorm8,
                         .doc = "the sketch over what the ordinary objects drew",
                         .tolerance = tolerance::kByte,
                         .tolerance_why = std::string(fed) + "; 8-bit target",
                         .frame_color = true,
                         .draws_over = {kComposeColor.name}},
                        {.handle = kSketchDepth,
                         .doc = "the sprite's normalized depth where the sketch was drawn, 1 elsewhere",
                         .tolerance = tolerance::kFloat,
                         .tolerance_why = std::string(fed) + "; float target"}},
            .effects = {"sketchy"},
            .declared_effects = {{"sketchy",
                                  "sketchy drawing of the objects whose style is sketchy (Nienhaus & Doellner "
                                  "2004); on by itself when one is",
                                  true}}};
  }
};

}  // namespace plumbago
