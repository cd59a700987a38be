// Crease and border points in the window (Kalnins et al. 2002, §4.5): the paths of line_meshes do
// not depend on the eye (their points are mesh vertices), so each backend keeps them and
// projects them each frame itself: the reference in double, the GPU in float from points
// uploaded once (shaders/strokes/crease_points.comp). With them, which faces around each
// segment face the eye: what the visibility test of a crease accepts besides its own key
// (common/strokes/visibility.hpp).
//
// Records: every point of every crease path, then of every border path, of each stroke
// object in scene order (the order window_lines lists them), kTableRow a row
// (common/util/image.hpp). Output per record:
//   - window: (x, y, d), the window position and linear view depth d = -z_view (a point
//     nearer than the near plane too: d says so);
//   - faces: for the segment from this point to the next of its path (a closed path's last
//     point to its first; none after an open path's last point), the keys of the first two
//     faces around its edge that face the eye, (k0, k1), 0 where none (common/strokes/strokes.hpp keys).
// Face keys are exact in a float below 2^24: a scene of more faces is refused.
//
// Parity is float against double: beyond 0.01, a derived per-record bound of the float
// projection's error (reference/strokes/float_error.hpp); a face's facing where
// n·(eye - x) lies within its float error of 0 (FLT_MAX: the keys may differ there).
#pragma once

#include <cstdint>
#include <vector>

#include "common/core/stage.hpp"
#include "common/strokes/line_meshes.hpp"

namespace plumbago {

inline constexpr Buffer kCreaseWindow{"crease_points.window"};
inline constexpr Buffer kCreaseFaces{"crease_points.faces"};
constexpr double kCreasePointPx = 1e-2;  // beyond which the derived bound must explain a difference

// One record: a point of a crease or border path and the faces around its segment to the
// next point (empty after an open path's last point). View-independent.
struct CreaseRecord {
  uint32_t object, vertex;
  std::vector<uint32_t> faces;  // the object's faces around the edge, in EdgeFaces order
};

// The records of the scene's stroke objects in table order. Throws std::length_error for a
// scene of 2^24 faces or more.
std::vector<CreaseRecord> crease_records(const Scene& scene, const LineMeshes& meshes);

struct CreasePointsStage {
  using Params = TypeList<>;
  static StageDesc describe() {
    return {.name = "crease_points",
            .kind = StageKind::Frame,
            .doc =
                "crease and border points projected to the window, and the faces around each segment that face "
                "the eye (Kalnins et al. 2002, §4.5)",
            .inputs = {{.handle = kLineMeshes}},
            .outputs = {{.handle = kCreaseWindow,
                         .channels = 3,
                         .doc = "(x, y, d): window position (px) and linear view depth, one texel per path point",
                         .tolerance = kCreasePointPx,
                         .tolerance_why = "float against double: beyond 0.01, a derived per-point bound of the "
                                          "projection's float error"},
                        {.handle = kCreaseFaces,
                         .channels = 2,
                         .doc = "(k0, k1): keys of the faces around the segment to the next point that face the "
                                "eye, 0 where none",
                         .tolerance_why = "exact, except where a face's n·(eye - x) is within its float error of "
                                          "0 (a derived bound; the note counts them)"}},
            .effects = {"line_tables"}};
  }
};

}  // namespace plumbago
