// The sketchy drawing of one scene from one camera, in each mode compared by the
// shower-door experiment: the (u, v) perturbation field (SPEC 3.2, 3.5) and the final
// sketch (SPEC 3.3), made with the reference passes exactly as reference/pipeline.cpp
// wires them.
#pragma once

#include <string>
#include <vector>

#include "common/sketchy.hpp"
#include "reference/gbuffer.hpp"
#include "reference/sketchy_maps.hpp"

namespace plumbago::shower_door {

// One mode: a sketchy style (SPEC 3.5) or a diagnostic variant of one.
struct Mode {
  std::string name;
  Scene scene;         // the sketchy objects with this mode's sketchy.* parameters
  SketchyNoise noise;  // made once: the same noise in every frame, as in an animation
  Scene enlarged;      // object styles: the enlarged objects (paper §4.2); no objects otherwise
  bool perturbed = true;
};

// The modes a name stands for: "default", "repeat", "rough", "object" (SPEC 3.5);
// "object_enlarge0" (object with sketchy.enlarge = 0: noise read on the true surface);
// "unperturbed" (default with M_e = M_s = 0: the sketch without any perturbation, a
// baseline for the rendered images). Throws on an unknown name.
Mode make_mode(const Scene& sketchy, const std::string& name);
std::vector<std::string> all_mode_names();

// What every mode shares at one camera: the sketchy G-buffer and maps (SPEC 3.1).
struct View {
  Scene scene;  // the sketchy objects seen from this camera
  GBuffer gbuffer;
  reference::SketchyMaps maps;
};
View trace_view(const Scene& sketchy, const Camera& camera);

struct ModeFrame {
  Image field;   // (u, v) at each pixel center, 2 ch per edge copy (repeat: edge_copies); empty if unperturbed
  Image sketch;  // 3 ch: the sketch over white paper (reference::sketchy_composite)
};
ModeFrame render_mode(const Mode& mode, const View& view);

}  // namespace plumbago::shower_door
