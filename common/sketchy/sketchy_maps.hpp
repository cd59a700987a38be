// Sketchy drawing's maps (Nienhaus & Döllner 2004, §3.1): the edge map of the sketchy objects (contour
// darkness of Nienhaus & Döllner 2003, as given in Pacheco §2 and the depth it belongs to) and their shade map (unlit
// color).
#pragma once

#include "common/pencil/edge_detect.hpp"
#include "common/core/stage.hpp"
#include "common/sketchy/sketchy_gbuffer.hpp"

namespace plumbago {

inline constexpr Buffer kSketchyEdge{"sketchy_maps.edge"};
inline constexpr Buffer kSketchyShade{"sketchy_maps.shade"};

struct SketchyMapsStage {
  using Params = TypeList<>;
  static StageDesc describe() {
    return {"sketchy_maps", StageKind::Frame, "edge and shade maps of the sketchy objects (SPEC 3.1)", {"edge"},
            {{kSketchyGBuffer.normal, EdgeDetectStage::smooth_normals},
             {kSketchyGBuffer.face_normal, EdgeDetectStage::face_normals},
             {kSketchyGBuffer.depth}, {kSketchyGBuffer.ids}},
            {{kSketchyEdge, 2, Texel::Float, "contour darkness d and the linear depth it belongs to", tolerance::kFloat,
              "fed the same sketchy G-buffer; float target"},
             {kSketchyShade, 4, Texel::Unorm8, "the object's unlit color, alpha = coverage", tolerance::kByte,
              "object colors and coverage; 8-bit target"}}};
  }
};

}  // namespace plumbago
