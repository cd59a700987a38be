// The view-independent part of the feature lines (Kalnins et al. 2002, §4.5), made once per
// scene and parameters: per stroke object, the crease-aware vertex normals, the crease and
// border paths and the edge-to-face adjacency (common/strokes/feature_lines.hpp). The ID
// image reads it every frame instead of making it again.
#pragma once

#include "common/core/stage.hpp"
#include "common/strokes/strokes.hpp"

namespace plumbago {

inline constexpr Slot<LineMeshes> kLineMeshes{"line_meshes.meshes"};

struct Preprocessed;
struct LineMeshesStage {
  using Params = TypeList<>;  // reads strokes.* (the crease angle), which the ID image declares
  static void make(const Scene& scene, Preprocessed& out);
  static StageDesc describe() {
    return {.name = "line_meshes",
            .kind = StageKind::Preprocessing,
            .doc =
                "crease-aware vertex normals, creases, borders and edge adjacency of the stroke objects "
                "(Kalnins et al. 2002, §4.5)",
            .params = {"strokes"},
            .outputs = {{.handle = kLineMeshes,
                         .channels = 0,
                         .texel = Texel::Host,
                         .doc = "per scene object: its feature-line mesh, none where not drawn with strokes"}},
            .preprocess = make};
  }
};

}  // namespace plumbago
