// The brush parameters of coherent silhouettes (Kalnins, Davidson, Markosian and Finkelstein
// 2003; the method: common/strokes/coherent_silhouettes.hpp), the stage that runs where
// `strokes.coherent` is on: each visible silhouette run's parameter t, voted for by the brush
// samples the path's previous frame drew and fitted, and the brush path whose offsets it draws,
// which the stroke raster draws; and this frame's brush samples, for the next frame's votes.
//
// A frame reads the samples of the frame before it on the camera path only where its renderer
// drew that one last (the reference: FrameOptions::carry; a GPU renderer: its last frame). In
// the viewer every frame follows the one before it (gpu::Renderer::follow_every_frame), so its
// orbit carries too. A frame that follows none (the first, or one drawn alone) has no votes:
// t = s, the 2002 paper's arc length from each run's start. PathFrames (render, bench, the
// Python module) draws the frames before the one asked for first, so that frame k of a path
// is the same whether the path is drawn in order or frame k alone.
#pragma once

#include <vector>

#include "common/core/stage.hpp"
#include "common/strokes/coherent_silhouettes.hpp"
#include "common/strokes/id_image.hpp"
#include "common/strokes/visibility.hpp"

namespace plumbago {

inline constexpr Slot<std::vector<RunBrush>> kBrushParameters{"brush_parameters.parameters"};
inline constexpr Slot<std::vector<BrushSample>> kBrushSamples{"brush_parameters.samples"};

// Whether silhouettes are coherent (`strokes.coherent`): then the stage runs, and a
// synthesized style's silhouettes draw their brush paths' offsets, new ones where the stage's
// are not there (a still frame on the GPU, a stage fed alone in parity).
inline bool strokes_coherent(const ParamSet& p) { return p.value("strokes.coherent") != 0.0; }
namespace when {
inline bool strokes_coherent(const StageConfig& c) { return plumbago::strokes_coherent(c.params); }
}  // namespace when

struct BrushParametersStage {
  using Params = TypeList<CoherenceParams>;
  static StageDesc describe() {
    return {
        .name = "brush_parameters",
        .kind = StageKind::Frame,
        .doc = "silhouette brush parameters carried over the surface from frame to frame (Kalnins et al. 2003)",
        .params = {"strokes", "coherence"},
        .inputs = {{.handle = kWindowLines}, {.handle = kVisibleRuns}},
        .outputs = {{.handle = kBrushParameters,
                     .channels = 0,
                     .texel = Texel::Host,
                     .doc = "per visible run: its knots (s, t), none: t = s; its brush path (the GPU keeps its fit on "
                            "the GPU)"},
                    {.handle = kBrushSamples,
                     .channels = 0,
                     .texel = Texel::Host,
                     .doc = "the silhouettes' surface points every coherence.sample_px, their t and brush path, which "
                            "the next frame's votes read (the GPU keeps its own on the GPU)"}}};
  }
};

}  // namespace plumbago
