// The `object` style's enlarged geometry (Nienhaus & Döllner §4.2-4.3): each
// pixel holds the 3D noise coordinate of the enlarged surface it sees (common/sketchy/sketchy.hpp).
#pragma once

#include "common/core/stage.hpp"

namespace plumbago {

inline constexpr Buffer kNoiseCoordinates{"sketchy_enlarged.noise_coordinates"};

struct SketchyEnlargedStage {
  using Params = TypeList<>;
  static StageDesc describe() {
    return {"sketchy_enlarged", StageKind::Frame, "noise coordinates on the enlarged sketchy objects (SPEC 3.5, object style)",
            {"sketchy"}, {},
            {{kNoiseCoordinates, 4, Texel::Float, "noise coordinate, alpha = coverage", tolerance::kBary,
              "raster vs ray on the enlarged objects; pixels covered with their 3x3 neighborhood in both; "
              "tolerance of the barycentrics (the coordinates are below 1)",
              ParityMask::Covered}}};
  }
};

}  // namespace plumbago
