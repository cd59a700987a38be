// The viewer's drawing on the model (Kalnins et al. 2002): the strokes drawn
// (apps/viewer/drawing.hpp) and every way they change, from the mouse, the keys, the panel or
// a script, each change shown at once (Session::set_drawn).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "apps/viewer/drawing.hpp"
#include "apps/viewer/session.hpp"
#include "apps/viewer/window.hpp"

namespace plumbago {

// What a left drag over the frame does.
enum class LeftDrag { Orbit, Draw, Erase };

class DrawingTool {
 public:
  DrawingTool(Session& session, Window& window) : session_(session), window_(window) {}

  const Drawing& drawing() const { return drawing_; }
  // What the last stroke, erasure or save came to, for the panel.
  const std::string& status() const { return status_; }
  void set_status(std::string status) { status_ = std::move(status); }

  // Ctrl+Z, Ctrl+Y: undo, redo. `mode` Draw: a left drag's frame points (`at`, origin
  // bottom-left; -1s off the frame) are shown as drawn and made a stroke of `settings` on
  // release; Erase: a click erases the stroke under it. Refusals go to status().
  void handle_input(glm::dvec2 at, LeftDrag mode, const DrawRequest& settings);

  // Draws `request` in the current view, or refuses it, drawing nothing (std::exception): a
  // stroke file would refuse it, the scene would (a hatching group's strokes all free or
  // all structured, ...), or a decal or hatch lies on no object drawn in strokes style.
  void draw(const DrawRequest& request);
  bool undo();                // whether there was a stroke
  bool redo();                // whether there was one undone
  void erase(size_t stroke);  // in the order drawn
  // The decal or hatch within kEraserPx of frame point `at`, in this view; whether one was.
  bool erase_at(glm::dvec2 at);
  // Writes the drawn strokes' files (Drawing::save); a saved scene then lists them.
  void save(const std::string& path);

  static constexpr double kEraserPx = 6;

 private:
  bool changed(bool change);  // shows the drawing when `change`; returns it
  Session& session_;
  Window& window_;
  Drawing drawing_;
  std::vector<DrawnPoint> sketch_;  // the stroke being drawn: frame points
  std::vector<glm::vec2> cursor_;   // and where the cursor was, in ImGui's coordinates
  std::string status_;
};

}  // namespace plumbago
