// Silhouette segments face by face (Kalnins et al. 2002, §4.5, "the zero set of n·(c - x)"):
// the first stroke stage that each backend computes itself. Per face corner,
// g = n·normalize(eye - x) with the crease-aware normals of line_meshes; per face, the
// segment where g changes sign, with the crossing rule, the g = 0 convention and the
// front/back test of common/strokes/feature_lines.hpp. The reference evaluates it in double
// (FeatureLineMesh::face_silhouette); the GPU in float, one invocation per face
// (shaders/strokes/silhouette_segments.comp), from corners, normals and slot orientations
// uploaded once per scene.
//
// Output: one record per face of the scene at its face key - 1 (first_faces in common/strokes/strokes.hpp;
// the faces of objects not drawn with strokes hold none), kTableRow records a row
// (common/util/image.hpp):
//   - ends: the window positions (x0, y0, x1, y1) of the crossings it enters and leaves by;
//   - facing: 1 front-facing, -1 back-facing, 0 no segment;
//   - slots: the slots it enters and leaves by (slot k: the edge from corner k to k + 1).
// Orientation: a segment runs with g > 0 on its left, seen from the side the face normal
// points to. It follows from the signs alone (oriented_slots, common/strokes/feature_lines.hpp),
// so both backends orient alike wherever they agree on them.
// A segment with an end nearer than the near plane is left out: the paths split there.
//
// They run in every stroke frame: the GPU's ID image draws the silhouettes of its own
// tables (common/strokes/silhouette_paths.hpp), the reference's its chains in double
// (common/strokes/strokes.hpp), and parity compares the tables.
//
// Parity is float against double. Where the reference's g at a corner of a face lies within
// the float evaluation error of 0, the backends may disagree on its sign and so on the
// segment: those faces are counted and excused. Elsewhere the ends may differ by the
// derived error of t = g_a / (g_a - g_b) and of the float projection
// (reference/strokes/silhouette_segments.cpp).
#pragma once

#include <cstdint>

#include "common/core/stage.hpp"
#include "common/strokes/line_meshes.hpp"

namespace plumbago {

inline constexpr Buffer kSegmentEnds{"silhouette_segments.ends"};
inline constexpr Buffer kSegmentFacing{"silhouette_segments.facing"};
inline constexpr Buffer kSegmentSlots{"silhouette_segments.slots"};

// The ends' tolerance in px, beyond which the derived per-face bound must explain a difference.
constexpr double kSegmentEndPx = 1e-2;

struct SilhouetteSegmentsStage {
  using Params = TypeList<>;  // reads strokes.silhouette_normalized, which the ID image declares
  static StageDesc describe() {
    return {.name = "silhouette_segments",
            .kind = StageKind::Frame,
            .doc =
                "per face, the silhouette segment where g = n·normalize(eye - x) changes sign, and its facing "
                "(Kalnins et al. 2002, §4.5)",
            .params = {"strokes"},
            .inputs = {{.handle = kLineMeshes}},
            .outputs = {{.handle = kSegmentEnds,
                         .channels = 4,
                         .doc = "(x0, y0, x1, y1): the window positions of the crossings it enters and leaves by, "
                                "one texel per face",
                         .tolerance = kSegmentEndPx,
                         .tolerance_why = "float against double: beyond 0.01 px, a derived per-face bound (the "
                                          "error of t and of the projection; any difference where a corner's g "
                                          "is within its float error of 0)"},
                        {.handle = kSegmentFacing,
                         .doc = "1 front-facing, -1 back-facing, 0 no segment, one texel per face",
                         .tolerance_why = "exact, except at faces where a corner's g or the facing test is within "
                                          "its float error of 0 (a derived bound; the note counts them)"},
                        {.handle = kSegmentSlots,
                         .channels = 2,
                         .doc = "(entry, exit): the slots it enters and leaves by, 0 where no segment",
                         .tolerance_why = "from the signs of g alone: exact where the facing's bound holds"}},
            .effects = {"line_tables"},
            .declared_effects = {{"line_tables",
                                  "the feature lines of the stroke objects as tables computed by each backend: "
                                  "silhouette segments per face, their chains with arc length and their paths, "
                                  "crease and border points in the window (Kalnins et al. 2002, §4.5); a stroke "
                                  "frame makes the silhouette tables anyway (the GPU draws its own), the crease "
                                  "points only on request"}}};
  }
};

}  // namespace plumbago
