// The `object` style's enlarged geometry (Nienhaus & Döllner §4.2-4.3): each
// pixel holds the 3D noise coordinate of the enlarged surface it sees (common/sketchy/sketchy.hpp).
#pragma once

#include "common/core/stage.hpp"

namespace plumbago {

inline constexpr Buffer kNoiseCoordinates{"sketchy_enlarged.noise_coordinates"};

struct SketchyEnlargedStage {
  using Params = TypeList<>;
  static StageDesc describe() {
    return {
        .name = "sketchy_enlarged",
        .kind = StageKind::Frame,
        .doc = "noise coordinates on the enlarged sketchy objects (Nienhaus & Döllner 2004, §3.4, §4; object style)",
        .params = {"sketchy"},
        .outputs = {{.handle = kNoiseCoordinates,
                     .channels = 4,
                     .doc = "noise coordinate, alpha = coverage",
                     .tolerance = tolerance::kBary,
                     .tolerance_why = "raster vs ray on the enlarged objects; pixels covered with their 3x3 "
                                      "neighborhood in both; tolerance of the barycentrics (the coordinates are "
                                      "below 1)",
                     .mask = ParityMask::Covered}}};
  }
};

}  // namespace plumbago
