// The G-buffer of the objects whose style is sketchy (Nienhaus & Döllner 2004, §3.1): the G-buffer of 2.1 drawn
// for them alone, which their edge and shade maps read.
#pragma once

#include "common/core/stage.hpp"
#include "common/scene/gbuffer.hpp"

namespace plumbago {

inline constexpr GBufferSlot kSketchyGBuffer{
    "sketchy_gbuffer",           {"sketchy_gbuffer.normal"},    {"sketchy_gbuffer.face_normal"},
    {"sketchy_gbuffer.depth"},   {"sketchy_gbuffer.ids"},       {"sketchy_gbuffer.bary"},
    {"sketchy_gbuffer.gouraud"}, {"sketchy_gbuffer.theta_min"}, {"sketchy_gbuffer.theta_max"}};

struct SketchyGBufferStage {
  using Params = TypeList<>;
  static StageDesc describe() {
    return {.name = "sketchy_gbuffer",
            .kind = StageKind::Frame,
            .doc = "G-buffer of the objects whose style is sketchy (Nienhaus & Döllner 2004, §3.1)",
            .params = {"gbuffer"},
            .outputs = gbuffer_outputs(kSketchyGBuffer, false)};
  }
};

}  // namespace plumbago
