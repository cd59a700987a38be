#include "reference/pipeline.hpp"

#include <functional>
#include <stdexcept>

#include "common/compose.hpp"
#include "common/edge_detect.hpp"
#include "common/passes.hpp"
#include "common/preprocess.hpp"
#include "common/lights.hpp"
#include "reference/compose.hpp"
#include "reference/contour_light.hpp"
#include "reference/multi_contour.hpp"
#include "reference/edge_detect.hpp"
#include "reference/gbuffer.hpp"
#include "reference/interior_intensity.hpp"
#include "reference/pencil_interior.hpp"
#include "reference/sketchy_composite.hpp"
#include "reference/sketchy_enlarged.hpp"
#include "reference/sketchy_maps.hpp"

namespace plumbago::reference {

namespace {

// The buffers passes hand to each other within one frame.
struct FrameState {
  Scene ordinary, sketchy;  // the objects each pipeline draws (common/sketchy.hpp)
  Preprocessed pre;
  GBuffer gbuffer;
  Image contour_darkness;
  Image lit_contour_darkness;
  Image multi_contour_darkness;
  Image interior_intensity;
  Image interior_darkness;
  Image color;
  GBuffer sketchy_gbuffer;
  Image noise_coordinates;
  SketchyMaps sketchy_maps;
  SketchyFrame sketch;
};

using PassFn = std::function<void(const Scene&, FrameState&)>;

const std::map<std::string, PassFn>& passes() {
  static const std::map<std::string, PassFn> table = {
      {"gbuffer",
       [](const Scene& s, FrameState& f) { f.gbuffer = trace_gbuffer(f.ordinary, s.width, s.height, f.pre.curvature); }},
      {"edge_detect",
       [](const Scene& s, FrameState& f) {
         f.contour_darkness = contour_darkness(f.gbuffer, s.params.get<EdgeDetectParams>());
       }},
      {"contour_light",
       [](const Scene& s, FrameState& f) {
         f.lit_contour_darkness = lit_contour_darkness(f.contour_darkness, f.gbuffer, view_space_lights(s),
                                                       s.params.get<ContourLightParams>());
       }},
      {"multi_contour",
       [](const Scene& s, FrameState& f) {
         f.multi_contour_darkness = multi_contour_darkness(f.lit_contour_darkness, f.pre.offset_grids,
                                                           f.pre.contour_texture, f.pre.texture_shifts,
                                                           s.params.get<ContourParams>());
       }},
      {"interior_intensity",
       [](const Scene& s, FrameState& f) {
         f.interior_intensity = interior_intensity(f.gbuffer, view_space_lights(s), s.params.get<InteriorParams>());
       }},
      {"pencil_interior",
       [](const Scene& s, FrameState& f) {
         f.interior_darkness = interior_darkness(f.gbuffer, f.interior_intensity, f.pre.pencil_stack,
                                                 f.pre.paper.normal, interior_options(s.effects),
                                                 s.params.get<InteriorParams>(), s.params.get<PaperParams>().mu_p);
       }},
      {"compose",
       [](const Scene& s, FrameState& f) {
         Image no_contours(s.width, s.height, 1);
         f.color = compose(f.multi_contour_darkness.empty() ? no_contours : f.multi_contour_darkness,
                           f.interior_darkness, f.pre.paper.color, s.params.get<ComposeParams>());
       }},
      {"sketchy_gbuffer",
       [](const Scene& s, FrameState& f) { f.sketchy_gbuffer = trace_gbuffer(f.sketchy, s.width, s.height); }},
      {"sketchy_enlarged",
       [](const Scene& s, FrameState& f) {
         f.noise_coordinates = enlarged_noise_coordinates(enlarged_scene(f.sketchy), s.width, s.height);
       }},
      {"sketchy_maps",
       [](const Scene& s, FrameState& f) {
         f.sketchy_maps = sketchy_maps(f.sketchy_gbuffer, object_colors(f.sketchy), s.params.get<EdgeDetectParams>());
       }},
      {"sketchy_composite",
       [](const Scene& s, FrameState& f) {
         SketchyInputs in{f.sketchy_maps, f.sketchy_gbuffer, f.pre.sketchy_noise, f.noise_coordinates};
         f.sketch = sketchy_composite(in, s.params.get<SketchyParams>(), f.color, f.gbuffer.depth);
         f.color = f.sketch.color;
       }},
  };
  return table;
}

}  // namespace

Frame render(const Scene& scene, const FrameOptions& options) {
  FrameState state;
  state.ordinary = ordinary_objects(scene);
  state.sketchy = sketchy_objects(scene);
  Frame frame;
  std::vector<std::string> all = passes_for(scene.effects, scene.params);
  state.pre = preprocess(state.ordinary, all);
  frame.ran = state.pre.ran;
  for (const std::string& name : frame_stages(all)) {
    auto it = passes().find(name);
    if (it == passes().end()) throw std::runtime_error("pass '" + name + "' is not implemented on the reference backend");
    Stopwatch watch;
    it->second(scene, state);
    frame.ran.push_back({name, watch.ms()});
  }
  frame.color = state.color;
  if (options.keep_buffers) {
    if (!state.gbuffer.depth.empty()) add_gbuffer_buffers(state.gbuffer, frame.buffers);
    if (!state.sketchy_gbuffer.depth.empty()) add_gbuffer_buffers(state.sketchy_gbuffer, frame.buffers, "sketchy_gbuffer");
    auto keep = [&](const char* name, const Image& img) {
      if (!img.empty()) frame.buffers[name] = img;
    };
    keep("edge_detect.contour_darkness", state.contour_darkness);
    keep("contour_light.lit_contour_darkness", state.lit_contour_darkness);
    keep("multi_contour.contour_darkness", state.multi_contour_darkness);
    keep("interior_intensity.intensity", state.interior_intensity);
    keep("pencil_interior.interior_darkness", state.interior_darkness);
    keep(state.sketch.color.empty() ? "compose.color" : "sketchy_composite.color", state.color);
    keep("sketchy_enlarged.noise_coordinates", state.noise_coordinates);
    keep("sketchy_maps.edge", state.sketchy_maps.edge);
    keep("sketchy_maps.shade", state.sketchy_maps.shade);
    keep("sketchy_composite.depth", state.sketch.depth);
  }
  return frame;
}

}  // namespace plumbago::reference
