// Sketchy drawing's maps (Nienhaus & Döllner 2004, §3.1): the edge map of the sketchy objects (contour
// darkness of Nienhaus & Döllner 2003, as given in Pacheco §2 and the depth it belongs to) and their shade map (unlit
// color).
#pragma once

#include "common/core/stage.hpp"
#include "common/pencil/edge_detect.hpp"
#include "common/sketchy/sketchy_gbuffer.hpp"

namespace plumbago {

inline constexpr Buffer kSketchyEdge{"sketchy_maps.edge"};
inline constexpr Buffer kSketchyShade{"sketchy_maps.shade"};

struct SketchyMapsStage {
  using Params = TypeList<>;
  static StageDesc describe() {
    return {.name = "sketchy_maps",
            .kind = StageKind::Frame,
            .doc = "edge and shade maps of the sketchy objects (Nienhaus & Döllner 2004, §3.1)",
            .params = {"edge"},
            .inputs = {{.handle = kSketchyGBuffer.normal, .used = EdgeDetectStage::smooth_normals},
                       {.handle = kSketchyGBuffer.face_normal, .used = EdgeDetectStage::face_normals},
                       {.handle = kSketchyGBuffer.depth},
                       {.handle = kSketchyGBuffer.ids}},
            .outputs = {{.handle = kSketchyEdge,
                         .channels = 2,
                         .doc = "contour darkness d and the linear depth it belongs to",
                         .tolerance = tolerance::kFloat,
                         .tolerance_why = "fed the same sketchy G-buffer; float target"},
                        {.handle = kSketchyShade,
                         .channels = 4,
                         .texel = Texel::Unorm8,
                         .doc = "the object's unlit color, alpha = coverage",
                         .tolerance = tolerance::kByte,
                         .tolerance_why = "object colors and coverage; 8-bit target"}}};
  }
};

}  // namespace plumbago
