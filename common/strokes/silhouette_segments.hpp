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
// points to (as the traced paths of common/strokes/feature_lines.hpp). It follows from the
// signs alone (oriented_slots below), so both backends orient alike wherever they agree on them.
// A segment with an end nearer than the near plane is left out: the paths split there.
//
// They run where a scene asks for the effect `line_tables` (compare and the tests add it):
// the stroke stages do not read them yet.
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

// The slots a segment that crosses slots s0 < s1 enters and leaves by. The corner c between
// them is the one whose g has the other sign; for a counter-clockwise face, the segment from
// slot c - 1 to slot c has c on its right, so it runs from slot c to slot c - 1 when
// g(c) > 0 and the other way otherwise.
struct SegmentSlots {
  int entry, exit;
};
constexpr int lone_corner(int s0, int s1) { return s1 == s0 + 1 ? s1 : 0; }
constexpr SegmentSlots oriented_slots(int s0, int s1, bool lone_corner_positive) {
  int c = lone_corner(s0, s1), before = (c + 2) % 3;
  return lone_corner_positive ? SegmentSlots{c, before} : SegmentSlots{before, c};
}

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
                                  "silhouette segments per face and their chains with arc length, crease and border "
                                  "points in the window (Kalnins et al. 2002, §4.5); on request: the stroke frame "
                                  "does not read them yet"}}};
  }
};

}  // namespace plumbago
