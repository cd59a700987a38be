// The viewer's drawing on the model: see apps/viewer/drawing_tool.hpp.
#include "apps/viewer/drawing_tool.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>  // key codes only
#include <imgui.h>

#include <stdexcept>
#include <utility>

#include "common/strokes/decal.hpp"
#include "gpu/strokes/decal.hpp"

namespace plumbago {

void DrawingTool::handle_input(glm::dvec2 at, LeftDrag mode, const DrawRequest& settings) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.KeyCtrl && !io.WantCaptureKeyboard) {
    if (ImGui::IsKeyPressed(GLFW_KEY_Z, false)) undo();
    if (ImGui::IsKeyPressed(GLFW_KEY_Y, false)) redo();
  }
  if (mode == LeftDrag::Erase && io.MouseClicked[ImGuiMouseButton_Left] && at.x >= 0) erase_at(at);
  if (mode != LeftDrag::Draw) {
    sketch_.clear(), cursor_.clear();
    return;
  }
  if (io.MouseDown[ImGuiMouseButton_Left] && at.x >= 0 &&
      (!sketch_.empty() || io.MouseClicked[ImGuiMouseButton_Left])) {
    if (sketch_.empty() || glm::distance(sketch_.back().window, at) >= 1) sketch_.push_back({at, 1.0});
    cursor_.emplace_back(io.MousePos.x, io.MousePos.y);
  }
  std::vector<ImVec2> line;
  for (glm::vec2 c : cursor_) line.emplace_back(c.x, c.y);
  if (!line.empty())
    ImGui::GetForegroundDrawList()->AddPolyline(line.data(), int(line.size()), IM_COL32(200, 40, 40, 255),
                                                ImDrawFlags_None, 2.0f);
  if (io.MouseDown[ImGuiMouseButton_Left] || sketch_.empty()) return;
  DrawRequest request = settings;
  request.points = std::exchange(sketch_, {});
  cursor_.clear();
  try {
    draw(request);
    status_ = "drew a " + stroke_role_names()[size_t(request.role)] + " stroke";
  } catch (const std::exception& e) {
    status_ = e.what();
  }
}

void DrawingTool::draw(const DrawRequest& request) {
  DrawnStroke stroke = drawn_stroke(session_.scene(), request);
  Drawing next = drawing_;
  next.add(session_.scene(), stroke);
  (void)decal_samples(session_.with_drawn(next.files()));  // the scene's own checks of its stroke files
  DrawnSurface surface;
  if (stroke.role == StrokeRole::Decal || stroke.role == StrokeRole::Hatching) {
    Scene probe = session_.scene();  // the stroke alone, projected through the G-buffer
    probe.stroke_files = {{"drawn stroke", probe.camera, probe.width, probe.height, "", {stroke}}};
    GpuScope gpu(window_);
    surface = drawn_surface(probe, gpu::project_decals_through_gbuffer(probe));
    if (surface.object == kMissed)
      throw std::invalid_argument(
          "the stroke misses the model: none of its samples lies on an object drawn in strokes style; nothing drawn");
  }
  drawing_.add(session_.scene(), std::move(stroke), std::move(surface));
  changed(true);
}

bool DrawingTool::undo() { return changed(drawing_.undo()); }
bool DrawingTool::redo() { return changed(drawing_.redo()); }

void DrawingTool::erase(size_t stroke) {
  drawing_.erase(stroke);
  changed(true);
}

bool DrawingTool::erase_at(glm::dvec2 at) {
  std::optional<size_t> hit = drawing_.stroke_near(session_.scene(), at, kEraserPx);
  status_ = hit ? "erased stroke " + std::to_string(*hit) : "no drawn stroke under the cursor";
  if (hit) erase(*hit);
  return hit.has_value();
}

void DrawingTool::save(const std::string& path) {
  std::vector<std::string> written = drawing_.save(path, session_.scene().origin);
  status_ = "wrote " + std::to_string(written.size()) + " stroke file(s) from " + path + "; Save scene lists them";
  changed(true);  // their sources now: what the scene file lists
}

bool DrawingTool::changed(bool change) {
  if (change) session_.set_drawn(drawing_.files());
  return change;
}

}  // namespace plumbago
