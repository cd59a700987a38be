#include "experiments/temporal_coherence/stroke_frames.hpp"

#include <algorithm>
#include <stdexcept>

#include "common/core/frame.hpp"
#include "common/scene/animation.hpp"
#include "common/scene/gbuffer.hpp"
#include "common/strokes/id_image.hpp"
#include "common/strokes/stroke.hpp"
#include "common/strokes/visibility.hpp"
#include "experiments/shower_door/surface_motion.hpp"
#include "reference/core/pipeline.hpp"
#include "reference/strokes/stroke.hpp"

namespace plumbago::temporal_coherence {

namespace {

constexpr int kDefaultFrames = 36;

}  // namespace

Scene study_scene(const std::string& path, const std::vector<std::string>& sets, std::optional<double> orbit_step_deg,
                  int frames) {
  Scene s = load_scene(path);
  if (!has_style(s, Style::Strokes)) throw std::runtime_error(path + ": no object has style strokes");
  for (const std::string& assignment : sets) s.params.set_assignment(assignment);
  s.effects.erase(std::remove(s.effects.begin(), s.effects.end(), "basecoat"), s.effects.end());
  if (orbit_step_deg) {
    int n = frames > 0 ? frames : s.animation ? s.animation->frames : kDefaultFrames;
    double fps = s.animation ? s.animation->fps : 30.0;
    s.animation = Animation{Animation::Kind::Orbit, *orbit_step_deg * (n - 1), n, fps};
  } else if (!s.animation) {
    throw std::runtime_error(path + ": no camera path (\"animation\"); give an orbit step");
  } else if (frames > 0) {
    throw std::runtime_error("a frame count changes an orbit given here, not the scene's own path");
  }
  return s;
}

StrokeFrame render_stroke_frame(const Scene& study, int t, CoherentCarry* coherent) {
  Scene s = scene_at_frame(study, t);
  std::vector<PassTime> ran;
  reference::ReferenceFrame f = reference::run_stages(s, ran);
  const Visibility* visibility = f.get(maybe(kVisibleRuns));
  if (!visibility) throw std::logic_error("the stroke stages did not run");
  const WindowLines& lines = f.get(kWindowLines);
  std::vector<BrushParameter> brushes;
  if (coherent) {
    Stopwatch watch;
    brushes = coherent_parameters(coherent->previous, s.camera, lines, *visibility, coherent->params);
    coherent->previous = brush_samples(lines, *visibility, brushes, coherent->params);
    coherent->ms.push_back(watch.ms());
  }
  std::vector<RunStroke> strokes = run_strokes(lines, *visibility, s.strokes, s.seed, brushes);
  Image layer = coherent ? reference::draw_strokes(stroke_triangles(strokes), s.seed, f.get(kPage), f.get(kPaperHeight),
                                                   s.params.get<StrokePaperParams>())
                               .color
                         : f.get(kStrokeColor);
  return {frame_strokes(s.camera, s.width, s.height, lines, *visibility, strokes), std::move(layer),
          shower_door::surface_points(world_geometry(f.ordinary), f.get(kGBuffer))};
}

}  // namespace plumbago::temporal_coherence
