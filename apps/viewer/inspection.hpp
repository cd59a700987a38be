// What the viewer shows besides the final image: the stage view, the reference check and
// the heat map of one of its results; which of them the frame area shows.
#pragma once

#include "apps/viewer/reference_check.hpp"
#include "apps/viewer/stage_view.hpp"

namespace plumbago {

struct Inspection {
  StageView stage;
  ReferenceCheck check;
  int heatmap = -1;  // the result of the check shown as its heat map, or none

  Image image(const Frame& frame) const { return heatmap >= 0 ? check.heatmap(size_t(heatmap)) : stage.image(frame); }
};

}  // namespace plumbago
