// Base strokes (Kalnins et al. 2002 §4.2, §5): a visible run of a
// path, in window pixels (origin bottom-left, docs/conventions.md), turned into samples and the
// triangles of a ribbon through them: the reference makes them here, in double (output float),
// and draws them with its scalar rasterizer; the GPU makes the same samples in double in a
// compute shader (1.-5., shaders/strokes/stroke_samples.comp), there too each sample's normal
// (6., once a run), and expands them into the same triangles in its vertex shader (6.,
// shaders/strokes/common_ribbon.glsl), in float.
//
// 1. Spline (Kalnins et al. 2002, §4.1). Input points that are not finite are dropped, and repeats (closer
//    than 1e-6 px) merged; a closed run's last point equal to its first is dropped. A
//    closed run needs 3 distinct points, with fewer it is drawn open. Non-uniform
//    Catmull-Rom: span p_i -> p_{i+1} of chord d is the cubic Hermite curve with end
//    tangents d v_i and d v_{i+1}, where
//      v_i = (p_{i+1} - p_{i-1}) / (|p_{i+1} - p_i| + |p_i - p_{i-1}|)
//    (docs/stages.md: tangent at p1 = (p2 - p0) |p2-p1| / (|p2-p1| + |p1-p0|)); |v_i| <= 1, so no span
//    overshoots. Parabolic end slopes: an open run's first span takes m0 = 2 (p1 - p0) - m1,
//    its last span m1 = 2 (p_n - p_{n-1}) - m0, which makes those spans parabolas that join
//    the next span's tangent. Two points give a straight segment.
// 2. Arc length. Each span is cut into m equal parameter steps, m = ceil(4 x the length of
//    its Bézier control polygon) (4 to 4096), so that no piece is longer than 0.75 px
//    (the speed of a cubic Bézier is at most 3 x its longest control leg; spans whose
//    polygon is over 1024 px long get longer pieces); positions between are interpolated
//    linearly in arc length. A chord h on a curve of radius r departs from it by at most
//    h^2 / (8 r) and is shorter than its arc by a share of about h^2 / (24 r^2): within
//    0.007 px and 0.03% where r >= 10 px.
// 3. Samples. The run of length L is cut into n = ceil(L / sample_px) equal pieces
//    (n + 1 samples, the first and last at the ends; a closed run's last sample is its
//    first again, at arc length L), so the step is sample_px or a little less. Where the
//    offsets lift or land the pen, a sample is added at exactly that arc length; an even
//    sample within 0.05 px of it is dropped, and so is a change within 0.05 px of an end of
//    the run, so that no drawn segment is shorter than that (in float, a segment of length l
//    turns its normal by up to 2^-22 C / l, C the window coordinate: at l = 1e-6 px an
//    arbitrary direction for the GPU's corners).
// 4. Offsets, rubber-stamped (Kalnins et al. 2002, §4.3, §5, App. A; Kalnins et al. 2003). At arc length s the
//    example's offset list is interpolated linearly at t = (s mod L_drawn) / L_drawn, wrapping from its last
//    offset to its first (period L_drawn); the displacement is scaled by
//    min(L / L_drawn, 1) (by 1 for an example that does not scale, OffsetExample::scales).
//    An offset with its break flag lifts the pen until the next offset: the ribbon is not drawn there, so it splits
//    into pieces. A lift of zero length (e.g. a break on an offset at t = 1 when the first is at t = 0) splits nothing.
//    An example made to span its run (OffsetExample::repeats false: a decal's pressure, a
//    synthesized example, whose L_drawn is the run's window length while its spline may be
//    a little longer) does not wrap: t = s / L_drawn is held in [0, 1], the first offset
//    before it and the last (its lift too) after it.
//    Samples move along the base curve's normal by the displacement. Where the run carries a
//    brush parameter (6.) and the example repeats, the example is stamped at t(s) instead of
//    s, its lifts and landings placed where t takes them (on each linear piece of t), so
//    that the offsets stay on the surface with the texture (Kalnins et al. 2003; a synthesized
//    style's example is then its brush path's, common/strokes/coherent_silhouettes.hpp 5.); an
//    example made to span its run stays on s.
// 5. Width and alpha per sample, dl = min(s, L - s) the distance to the nearer end (a closed
//    run has no ends: none of these apply):
//      taper  w x sqrt(1 - ((T - dl)/T)^2)             dl < T = taper_px
//      flare  w x (1 + flare (1 - 2 dl / L))          (reading, stroke_style.hpp)
//      fade   alpha x (1 - ((F - dl)/F)^2)^1.5         dl < F = fade_px
//      halo   h = (H - dh)/H, w x (1 - h^2)^0.25, alpha x (1 - h^2)^5,   dh < H = halo_px
//    with dh the distance to the nearer end caused by occlusion (StrokeRun::occluded_*);
//    reading: that is dl when the nearer end is occluded, and it keeps the halo continuous
//    when only the farther end is. Then the pressure (stroke_style.hpp), and last the
//    thin-stroke rule: a width w < 2 px gives alpha x w^2 / 4 and is drawn 2 px wide.
// 6. Ribbon. Normals are miter-free: at each sample the normalized sum of the left
//    normals of its two segments (one at a piece's ends; a closed run drawn whole wraps
//    around); a degenerate segment, or a hairpin whose two normals cancel, takes the
//    previous normal; a piece with no segment of nonzero length draws nothing. Sample p
//    of width w gives p - n w/2 (v = 0, right of the direction of travel) and p + n w/2
//    (v = 1, left), u = t / texture_period_px, t the brush parameter at s: s itself, or
//    where the run carries one, its coherent parameter (Kalnins et al. 2003,
//    common/strokes/coherent_silhouettes.hpp) at s scaled to its polyline's length.
//    Consecutive samples make a GL triangle strip R0 L0 R1 L1 ...; its triangles, in GL's
//    order and winding ((R_j, L_j, R_{j+1}), (R_{j+1}, L_j, L_{j+1})), are the output.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "common/strokes/stroke_style.hpp"

namespace plumbago {

// A run's brush parameter: knots (s, t), s the arc length along its polyline (px,
// ascending; two knots at one s: t jumps there); none: t = s.
using BrushParameter = std::vector<glm::dvec2>;

// t at s: linear between knots, extrapolated along the end intervals; s itself without knots.
double brush_t(const BrushParameter& knots, double s);

// A visible run of a path, window px. occluded_start / occluded_end: that end is where
// the path goes behind something (it gets the halo); both are ignored when closed.
struct StrokeRun {
  std::vector<glm::dvec2> points;
  bool closed = false;
  bool occluded_start = false, occluded_end = false;
  BrushParameter brush;  // t over its polyline's arc length (6. above); none: t = s
};

struct RibbonVertex {
  glm::vec2 position;  // window px
  glm::vec2 uv;        // u along (brush parameter / texture_period_px), v across (0..1)
  float alpha;
};

struct Ribbon {
  std::vector<RibbonVertex> triangles;  // 3 vertices each
  glm::vec3 color{0.0f};
};

// The spline of 1. above, resampled every spacing_px or a little less (3.): an open
// run's samples include both ends; a closed run's do not repeat the first. One distinct
// point gives itself, none gives none. Throws std::invalid_argument when spacing_px is not
// positive and finite or the curve would take more than 1e7 samples.
std::vector<glm::dvec2> catmull_rom_resample(const std::vector<glm::dvec2>& points, double spacing_px, bool closed);

// The example's offset at arc length s of a run of length run_length (4. above); the
// example must be one validate_stroke_style accepts.
struct StampedOffset {
  double displacement_px;  // already scaled by min(run_length / L_drawn, 1) where the example scales
  double pressure;
  bool pen_down;  // false inside a lift
};
StampedOffset rubber_stamp(const OffsetExample& example, double s, double run_length);

// One sample of a run's ribbon (3.-5. above): its position (offset applied, window px) and
// the base curve's point under it, its arc length s along the spline from the run's start
// (px), its brush parameter t (px; u = t / texture_period_px, 6. above), its width and alpha.
struct StrokeSample {
  glm::dvec2 position, base;
  double s, t, width, alpha;
  bool pen_down_after;  // the segment to the next sample is drawn
};

// The samples of one run, the length of its spline (px) and whether it is drawn as a loop.
struct BaseStrokeSamples {
  std::vector<StrokeSample> samples;
  double length_px = 0;
  bool closed = false;
};

// The samples of one run (1.-5.); none for a run of fewer than 2 distinct points. Throws
// StrokeStyleError for a style validate_stroke_style refuses, std::invalid_argument for a
// run that would take more than 1e7 samples.
BaseStrokeSamples base_stroke_samples(const StrokeRun& run, const StrokeStyle& style);

// The ribbon through a run's samples (6.), in the style's color; empty for fewer than 2.
Ribbon ribbon(const BaseStrokeSamples& stroke, const StrokeStyle& style);

// ribbon(base_stroke_samples(run, style), style): the ribbon of one run, with the same throws.
Ribbon base_stroke(const StrokeRun& run, const StrokeStyle& style);

}  // namespace plumbago
