// Decals (Kalnins et al. 2002 §3, "decal strokes"): strokes of the stroke files
// (common/strokes/stroke_file.hpp) fixed on the surface where they were drawn.
//
// 1. Projection, once per renderer. Each decal stroke's polyline is resampled every
//    kDecalStepPx px of the drawing (its ends kept, pressure interpolated linearly), so
//    that consecutive surface points lie close on the surface, and each sample p is
//    projected through the stroke file's camera at its resolution: the ray from the eye
//    through window point p (docs/conventions.md, PrimaryRays) meets the nearest face. It is kept as a
//    surface point: object, face, barycentrics (weights of the face's corners 0, 1, 2). A
//    sample whose ray meets nothing is kept as missed and splits the stroke. The backends
//    find the face each their own way:
//      - GPU (gpu/strokes/decal.cpp): the G-buffer rendered with that camera gives the faces seen
//        at the pixel centers of the 3x3 pixels around p (its ids); of those (or, when the
//        ray meets none, of the faces sharing a vertex with them: a sliver may cover no
//        pixel center), the one the ray through p meets first (decal_ray_hit, in double) is the face, and its
//        barycentrics are where the ray meets it (the G-buffer's own barycentrics are the
//        pixel center's, up to half a pixel away);
//      - reference (reference/strokes/decal.cpp): an Embree ray through p.
//    They differ only where p lies within about a pixel of a silhouette or on a face no
//    pixel center around it sees (tests/strokes/decal_test.cpp counts and bounds them).
// 2. Every frame, the surface points are placed in the world (the object's transform) and
//    projected to the window: a decal path (common/strokes/strokes.hpp, LineKind::Decal), split
//    where a sample missed, where the object changes and at the near plane. Its samples
//    are visible where the ID image holds their face's key (Kalnins et al. 2002, §4.6, SampleKind decal:
//    the face of the nearer path point), and its visible runs are drawn as base strokes
//    in the decal's style (common/strokes/stroke.hpp), after the feature lines.
// 3. Pressure: the drawn pressure, carried by the surface points, multiplies the width
//    (and/or alpha) through the style's pressure rule (common/strokes/stroke_style.hpp): each
//    visible run is given an offsets example of zero displacement whose pressure is the
//    path's over the run. It replaces the style's own offsets: a decal keeps its drawn
//    shape.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "common/scene/scene.hpp"
#include "common/strokes/hatching.hpp"

namespace plumbago {

constexpr double kDecalStepPx = 2.0;  // px of the drawing between projected samples
constexpr uint32_t kMissed = std::numeric_limits<uint32_t>::max();

// A surface stroke's samples in its file's window, before projection: a decal, or a hatch
// of a hatching group (Kalnins et al. 2002, §6, common/strokes/hatching.hpp), which is projected the same way.
struct DecalSamples {
  const StrokeFile* file;
  const StrokeStyle* style;
  HatchTag hatch;
  std::vector<DrawnPoint> samples;
};

// Every decal stroke of the scene's stroke files, file after file, then every hatch
// (hatch_polylines), resampled (1. above).
std::vector<DecalSamples> decal_samples(const Scene& scene);
// Whether the scene has decals or hatching.
bool has_decals(const Scene& scene);

// The polyline's length in px of its window.
double drawn_length(const std::vector<DrawnPoint>& points);
// `points` at segments + 1 even arc-length fractions, pressure interpolated linearly.
std::vector<DrawnPoint> resampled_evenly(const std::vector<DrawnPoint>& points, size_t segments);

struct DecalPoint {
  uint32_t object = kMissed, face = 0;  // object: index in scene.objects; kMissed: the ray met nothing
  glm::dvec3 bary{0.0};
  double pressure = 1;
};

struct ProjectedDecal {
  StrokeStyle style;
  std::vector<DecalPoint> points;
  HatchTag hatch;
};

// The object most of `objects` name (the lowest on a tie), kMissed where none is named: the
// object a hatching group, a mobile group or a drawn stroke lies on.
uint32_t most_common_object(const std::vector<uint32_t>& objects);

// Where a surface point lies on its object (object space), and in the world.
glm::dvec3 decal_point_local(const Scene& scene, const DecalPoint& p);
glm::dvec3 decal_point_world(const Scene& scene, const DecalPoint& p);

// One per decal stroke, in decal_samples' order: what a backend projects (the GPU once per
// renderer, the reference by rays each frame) and hands window_lines.
using DecalSurface = std::vector<ProjectedDecal>;

// The ray of window point p of `file`'s camera (docs/conventions.md): from the eye, unit direction.
struct DecalRay {
  glm::dvec3 origin, direction;
};
DecalRay decal_ray(const StrokeFile& file, glm::dvec2 p);

// Where `ray` meets triangle (a, b, c): distance and barycentrics (of a, b, c), both in
// double; none when it misses or meets it behind the eye.
struct RayTriangleHit {
  double t;
  glm::dvec3 bary;
};
std::optional<RayTriangleHit> decal_ray_hit(const DecalRay& ray, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c);

// How two projections of the same samples agree (tests/strokes/decal_test.cpp): points, those on
// the same object and face, the largest barycentric difference among those, and the
// points that differ, counted apart where `near_silhouette` (one flag per point, decal
// after decal) says the point lies within a pixel of a silhouette, or on an edge or corner
// of both faces (a barycentric under 1e-3 on each: which face holds it is rounding's call).
struct ProjectionAgreement {
  size_t points = 0, same_face = 0, differ_on_edge = 0, differ_near_silhouette = 0, differ_elsewhere = 0;
  double max_bary_difference = 0;
};
ProjectionAgreement compare_projections(const DecalSurface& a, const DecalSurface& b,
                                        const std::vector<uint8_t>& near_silhouette);

}  // namespace plumbago
