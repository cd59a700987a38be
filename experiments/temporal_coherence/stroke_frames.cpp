#include "experiments/temporal_coherence/stroke_frames.hpp"

#include <algorithm>
#include <stdexcept>

#include "common/core/frame.hpp"
#include "common/scene/animation.hpp"
#include "common/scene/gbuffer.hpp"
#include "common/strokes/brush_parameters.hpp"
#include "common/strokes/id_image.hpp"
#include "common/strokes/stroke.hpp"
#include "common/strokes/visibility.hpp"
#include "experiments/shower_door/surface_motion.hpp"
#include "reference/core/pipeline.hpp"

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

StrokeFrame render_stroke_frame(const Scene& study, int t, Carry* carry) {
  Scene s = scene_at_frame(study, t);
  std::vector<PassTime> ran;
  reference::ReferenceFrame f = reference::run_stages(s, ran, carry ? carry->before(t) : nullptr);
  const Visibility* visibility = f.get(maybe(kVisibleRuns));
  if (!visibility) throw std::logic_error("the stroke stages did not run");
  f.previous = nullptr;
  if (carry) *carry = {t, f.data};
  const WindowLines& lines = f.get(kWindowLines);
  const std::vector<RunBrush>* brushes = f.get(maybe(kBrushParameters));
  std::vector<RunStroke> strokes =
      run_strokes(lines, *visibility, s.strokes, s.seed, brushes ? *brushes : std::vector<RunBrush>{});
  StrokeFrame out{frame_strokes(s.camera, s.width, s.height, lines, *visibility, strokes), f.get(kStrokeColor),
                  shower_door::surface_points(world_geometry(f.ordinary), f.get(kGBuffer))};
  for (const PassTime& pass : ran)
    if (pass.name == "brush_parameters") out.coherence_ms = pass.ms;
  return out;
}

}  // namespace plumbago::temporal_coherence
