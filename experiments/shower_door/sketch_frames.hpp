// The sketchy drawing of one scene from one camera, in each mode compared by the
// shower-door experiment: the (u, v) perturbation field (Nienhaus & Döllner 2004, §3.2; §3.4, §4) and the final
// sketch (Nienhaus & Döllner 2004, §3.2), made with the reference passes exactly as reference/core/pipeline.cpp
// wires them.
#pragma once

#include <string>
#include <vector>

#include "common/sketchy/sketchy.hpp"
#include "reference/scene/gbuffer.hpp"
#include "reference/sketchy/sketchy_maps.hpp"

namespace plumbago::shower_door {

// One mode: a sketchy style (Nienhaus & Döllner 2004, §3.4, §4) or a diagnostic variant of one.
struct Mode {
  std::string name;
  Scene scene;         // the sketchy objects with this mode's sketchy.* parameters
  SketchyNoise noise;  // made once: the same noise in every frame, as in an animation
  Scene enlarged;      // object styles: the enlarged objects (paper §4.2); no objects otherwise
  bool perturbed = true;
};

// The modes a name stands for: "default", "repeat", "rough", "object" (Nienhaus & Döllner 2004, §3.4, §4);
// "object_enlarge<E>" (object with sketchy.enlarge = E; E = 0: noise read on the true
// surface);
// "unperturbed" (default with M_e = M_s = 0: the sketch without any perturbation, a
// baseline for the rendered images). Throws on an unknown name.
Mode make_mode(const Scene& sketchy, const std::string& name);
std::vector<std::string> all_mode_names();

// What every mode shares at one camera: the sketchy G-buffer and maps (Nienhaus & Döllner 2004, §3.1).
struct View {
  Scene scene;  // the sketchy objects seen from this camera
  GBuffer gbuffer;
  reference::SketchyMaps maps;
};
View trace_view(const Scene& sketchy, const Camera& camera);

struct ModeFrame {
  Image field;        // (u, v) at each pixel center, 2 ch per edge copy (repeat: edge_copies); empty if unperturbed
  Image sketch;       // 3 ch: the sketch over white paper (reference::sketchy_composite)
  Image coordinates;  // object styles: the enlarged surface's noise coordinates (4 ch); empty otherwise
};
ModeFrame render_mode(const Mode& mode, const View& view);

// Object styles, diagnostic: 1 ch, 1 where the enlarged surface seen at a covered pixel is
// the pixel's own surface point pushed out (within `reach` x the enlarge distance of the
// true surface point in `points`, surface_points' map), 0 where it belongs to another
// part of the object whose enlarged shell hides the true surface there (paper §4.2: the
// enlarged geometry is not the surface).
Image own_shell(const Mode& mode, const View& view, const Image& points, const Image& coordinates, float reach = 3.0f);

}  // namespace plumbago::shower_door
