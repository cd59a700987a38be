// The strokes of one frame as the temporal-coherence study follows them (docs/conventions.md, "Temporal
// coherence"; experiments/temporal_coherence/README.md): every visible run's base-stroke
// samples (common/strokes/stroke.hpp run_strokes, what the stroke stage draws), each with the point
// of its path it draws, and where those points land on the strokes of another frame.
// Nothing here depends on the line kind: a new kind's runs are followed like the others.
#pragma once

#include <optional>
#include <set>
#include <vector>

#include <glm/glm.hpp>

#include "common/scene/camera.hpp"
#include "common/strokes/stroke.hpp"

namespace plumbago::temporal_coherence {

// One base-stroke sample and the point of its path under it.
struct TrackedSample {
  glm::dvec3 world;   // the path's world point (world_at) at the sample's arc length
  glm::dvec2 window;  // that point in this frame's window (px)
  double depth;       // its linear view depth in this frame
  // As drawn: s the brush parameter (px; u x period: the arc length from the stroke's start, or
  // its coherent parameter, common/strokes/coherent_silhouettes.hpp), width (px), alpha.
  double s, width, alpha;
  glm::dvec2 offset;  // as drawn: the position minus the base curve's (px), the offsets of Kalnins et al. 2002,
                      // §4.3, §5, App. A
  double arc_px = 0;  // its arc length along the run's spline from the stroke's start (s = arc_px without a
                      // brush parameter)
};

// A visible run that draws something (2 samples or more).
struct TrackedRun {
  LineKind kind;
  uint32_t object;
  // A hash of its whole path's surface curve (object, kind, key, surface points): equal in
  // two frames when the path lies on the same points of the surface, as a crease, border
  // or decal does; a silhouette's changes as it moves over the surface.
  uint64_t curve;
  double length_px;  // its spline's length: s runs from 0 to this
  bool closed;       // drawn as a loop: s wraps around length_px
  std::vector<TrackedSample> samples;
};

struct FrameStrokes {
  Camera camera;
  int width = 0, height = 0;
  std::vector<TrackedRun> runs;
  std::set<uint64_t> curves;  // the curve of every path of the frame, drawn or hidden
};

// The tracked strokes of a frame seen by `camera` in a width x height window: run i of
// `visibility` drawn as strokes[i] (run_strokes of the same lines and visibility). Sample j
// of a run from s0 to s1 of its path draws the path point at s0 + s_j (s1 - s0) / L, L the
// spline's length (the spline and the path's polyline are within a fraction of a px).
FrameStrokes frame_strokes(const Camera& camera, int width, int height, const WindowLines& lines,
                           const Visibility& visibility, const std::vector<RunStroke>& strokes);

// Where a sample of one frame lands on the strokes of another.
struct Landing {
  size_t run;              // index in the other frame's runs
  double s, width, alpha;  // the other stroke's, interpolated at the nearest point
  glm::dvec2 offset;
  double distance_px;  // from the sample's reprojection to that point
};

struct MatchParams {
  double radius_px = 2.0;         // a reprojected sample lands on a stroke at most this far
  double depth_tolerance = 0.02;  // and whose depth there is within this share of its own
};

// Per run of `from`, per sample: its world point projected with `to`'s camera, landed on the
// nearest point (within radius_px, at a depth within depth_tolerance) of the polyline through
// the samples of a stroke of `to` of the same path curve when `to` has that path (drawn or
// hidden), else of the same
// line kind and object; none when no such stroke is that near. A path fixed on the surface
// (crease, border, decal) thus finds its own point again, or nothing where that point is now
// hidden (not a neighbouring crease 1 px away); a silhouette's point slides off the
// silhouette as the view turns, and lands on the new silhouette next to it (as Kalnins et
// al. 2003 carry their silhouette samples from frame to frame).
using Landings = std::vector<std::vector<std::optional<Landing>>>;
Landings carry(const FrameStrokes& from, const FrameStrokes& to, const MatchParams& params = {});

}  // namespace plumbago::temporal_coherence
