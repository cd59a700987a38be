// Edge detection (Nienhaus & Döllner 2003 as given in Pacheco §2).
//   I_n = clamp(1/2 (N_A.N_H + N_C.N_F), 0, 1)
//   I_z = (1 - min(1, s/2 |z_A - z_H|))^2 (1 - min(1, s/2 |z_C - z_F|))^2
//   contour darkness d = 1 - I_n I_z
// Neighbors A (top-left) .. H (bottom-right) one pixel apart, clamp-to-edge outside.
//
// Reading (docs/readings.md): background normals are (0,0,0), so taken literally every
// background pixel has I_n = 0 and is drawn as contour. With `background_pairs =
// continuous` (default) a pair of two background pixels counts as N.N = 1; a pair of an
// object and a background pixel keeps N.N = 0, so silhouettes stay dark. `formula` is
// the literal reading.
#pragma once

#include "common/core/stage.hpp"
#include "common/scene/gbuffer.hpp"

namespace plumbago {

enum class EdgeNormals { Interpolated, Face };
enum class BackgroundPairs { Continuous, Formula };

struct EdgeDetectParams {
  static constexpr const char* stage = "edge";
  float depth_scale;
  EdgeNormals normals;
  BackgroundPairs background_pairs;
  template <class V>
  void visit(V& v) {
    v.real(depth_scale, "depth_scale", 10.0, 0.0, 10000.0,
           "s in I_z: normalized-depth difference that darkens a contour (see docs/readings.md)");
    v.choice(normals, "normals", EdgeNormals::Interpolated, {"interpolated", "face"},
             "normals compared by I_n: shading (interpolated) or geometric (face)");
    v.choice(background_pairs, "background_pairs", BackgroundPairs::Continuous, {"continuous", "formula"},
             "N.N of two background pixels: 1 (continuous) or 0 as the zero normals give (formula)");
  }
};

// d of a background pixel whose neighbors are background too (Nienhaus & Döllner 2003, as given in Pacheco §2): 0, or 1
// under the literal formula (zero normals disagree).
inline float background_darkness(const EdgeDetectParams& p) {
  return p.background_pairs == BackgroundPairs::Continuous ? 0.0f : 1.0f;
}

inline constexpr Buffer kContourDarkness{"edge_detect.contour_darkness"};  // d

struct EdgeDetectStage {
  using Params = TypeList<EdgeDetectParams>;
  static bool face_normals(const StageConfig& c) {
    return c.params.get<EdgeDetectParams>().normals == EdgeNormals::Face;
  }
  static bool smooth_normals(const StageConfig& c) { return !face_normals(c); }
  static StageDesc describe() {
    return {.name = "edge_detect",
            .kind = StageKind::Frame,
            .doc = "contour darkness from normal and depth discontinuities (Nienhaus & Döllner 2003, as in Pacheco §2)",
            .params = {"edge"},
            .inputs = {{.handle = kGBuffer.normal, .used = smooth_normals},
                       {.handle = kGBuffer.face_normal, .used = face_normals},
                       {.handle = kGBuffer.depth}},
            .outputs = {{.handle = kContourDarkness,
                         .doc = "d = 1 - I_n I_z",
                         .tolerance = tolerance::kFloat,
                         .tolerance_why = "fed the same G-buffer; float target"}}};
  }
};

}  // namespace plumbago
