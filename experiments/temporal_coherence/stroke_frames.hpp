// The frames of the temporal-coherence study: a stroke scene along a camera path, each
// frame rendered by the CPU reference (reference::run_stages), kept as what the measures
// read: the tracked strokes (stroke_track.hpp), the stroke layer and the surface points.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/scene/scene.hpp"
#include "experiments/temporal_coherence/stroke_track.hpp"

namespace plumbago::temporal_coherence {

// The scene as the study renders it: `sets` (stage.param=value) applied, the base coat
// off (the strokes over the blank page: the stroke layer), and, when `orbit_step_deg` is
// given, its camera path replaced by an orbit of `frames` frames that many degrees apart
// (frames = 0: the scene's own frame count, or 36 when it has no path). Throws when the
// scene has no stroke object, or no camera path and no orbit is given.
Scene study_scene(const std::string& path, const std::vector<std::string>& sets, std::optional<double> orbit_step_deg,
                  int frames);

struct StrokeFrame {
  FrameStrokes strokes;
  Image layer;   // RGB: stroke.color, the strokes over the page (the paper's grain included)
  Image points;  // shower_door::surface_points of the frame's G-buffer: the surface seen at each pixel
  // The brush_parameters stage's time (ms, wall), where strokes.coherent ran it; else NaN.
  double coherence_ms = NAN;
};

// Frame t of the study scene's camera path, by the CPU reference's stages. With
// strokes.coherent (coherent silhouettes, Kalnins et al. 2003: the brush_parameters stage
// and its coherence.* parameters), the silhouettes' brush parameters are voted for by what
// `carry` holds of frame t - 1 (none before the first frame, or without a carry), and
// `carry` then holds frame t's.
StrokeFrame render_stroke_frame(const Scene& study, int t, Carry* carry = nullptr);

}  // namespace plumbago::temporal_coherence
