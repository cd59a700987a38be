// The viewer's panel (Dear ImGui). Every widget comes from a registry, none is written
// for one parameter: the parameters from param_specs() (grouped by stage prefix, range,
// default, doc as tooltip, reset), the effects from effect_table(), the styles from
// style_names().
#pragma once

#include <map>
#include <string>

#include "apps/viewer/drawing_tool.hpp"
#include "apps/viewer/inspection.hpp"
#include "apps/viewer/session.hpp"
#include "apps/viewer/timing.hpp"

namespace plumbago {

class Panels {
 public:
  // Draws the panel in the framebuffer's right `width` pixels.
  void draw(Session& session, Inspection& inspection, DrawingTool& drawing, glm::ivec2 framebuffer, float width);

  Timing timing;
  bool continuous = false;         // render every frame (for timing), not only after a change
  bool screenshot_wanted = false;  // the viewer writes `screenshot_path` after drawing
  std::string screenshot_path = "plumbago-view.png";
  // Drawing on the model (apps/viewer/drawing_tool.hpp): what a left drag does, what it draws.
  LeftDrag left_drag = LeftDrag::Orbit;
  DrawRequest draw_settings;

 private:
  void scene_section(Session& session);
  void camera_section(Session& session);
  void params_section(Session& session);
  // `slow`: preprocessing reads the parameter.
  void param_row(Session& session, const ParamSpec& spec, bool slow);
  void save_section(Session& session);
  void draw_section(const Session& session, DrawingTool& drawing);
  void drawn_list(const Session& session, DrawingTool& drawing);
  static bool stroke_rows(DrawingTool& drawing, const std::vector<size_t>& strokes);
  static void stage_section(Session& session, Inspection& inspection);
  static void reference_section(const Session& session, Inspection& inspection);
  // Values being dragged of parameters that preprocessing reads: applied on release,
  // so a drag does not remake the textures at every step.
  std::map<std::string, double> pending_;
  std::string scene_path_ = "plumbago-view.json", image_path_ = "plumbago-frame.png";
  std::string strokes_path_ = "plumbago-drawn.strokes.json";
  std::string status_;
  size_t drawn_shown_ = 0;  // the strokes drawn when the panel last drew: one more opens its section
};

}  // namespace plumbago
