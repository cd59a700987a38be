// Sketchy drawing's maps (Nienhaus & Döllner 2004, §3.1), CPU reference: the edge map of the sketchy objects
// and their shade map. The twin of gpu/sketchy/sketchy_maps.cpp.
#pragma once

#include <vector>

#include "common/pencil/edge_detect.hpp"
#include "common/scene/gbuffer.hpp"

namespace plumbago::reference {

struct SketchyMaps {
  // 2 ch: contour darkness d (Nienhaus & Döllner 2003, as given in Pacheco §2), and the linear depth d belongs to: the
  // nearest of the pixel and its diagonal neighbors A, C, F, H (the pixels d is made of); `far`
  // where all five are background.
  Image edge;
  Image shade;  // 4 ch: the object's unlit color, alpha = coverage (0 or 1)
};

// `colors`: one per object of the G-buffer's scene.
SketchyMaps sketchy_maps(const GBuffer& g, const std::vector<glm::vec3>& colors, const EdgeDetectParams& p);

}  // namespace plumbago::reference
