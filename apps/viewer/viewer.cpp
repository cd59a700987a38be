#include "apps/viewer/viewer.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>  // key codes only
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "apps/viewer/frame_image.hpp"
#include "apps/viewer/panels.hpp"
#include "apps/viewer/session.hpp"
#include "apps/viewer/window.hpp"

namespace plumbago {
namespace {

constexpr float kPanelWidth = 440;      // pixels right of the frame
constexpr int kPanelHeight = 720;       // the window's least height with the panel
constexpr float kDegreesPerPixel = 0.4f;
constexpr float kZoomPerNotch = 0.9f;

// Mouse and keys over the frame (not over the panel): left drag orbits, right or middle
// drag pans, the wheel zooms; R: the scene's camera, F: frame the scene.
void steer(Session& session, const Placement& frame) {
  const ImGuiIO& io = ImGui::GetIO();
  glm::vec2 d(io.MouseDelta.x, io.MouseDelta.y);
  bool moved = d != glm::vec2(0);
  if (!io.WantCaptureMouse && moved && io.MouseDown[ImGuiMouseButton_Left])
    session.move_camera([&](OrbitCamera& o) { o.orbit(-d.x * kDegreesPerPixel, d.y * kDegreesPerPixel); });
  if (!io.WantCaptureMouse && moved && (io.MouseDown[ImGuiMouseButton_Right] || io.MouseDown[ImGuiMouseButton_Middle]))
    session.move_camera([&](OrbitCamera& o) { o.pan(glm::vec2(d.x, -d.y) / float(std::max(frame.size.y, 1))); });
  if (!io.WantCaptureMouse && io.MouseWheel != 0)
    session.move_camera([&](OrbitCamera& o) { o.zoom(std::pow(kZoomPerNotch, io.MouseWheel)); });
  if (io.WantCaptureKeyboard) return;
  if (ImGui::IsKeyPressed(GLFW_KEY_R, false)) session.move_camera([](OrbitCamera& o) { o.reset(); });
  if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) session.move_camera([](OrbitCamera& o) { o.frame(); });
}

bool screenshot_key() { return !ImGui::GetIO().WantCaptureKeyboard && ImGui::IsKeyPressed(GLFW_KEY_P, false); }

// The part of the window the frame gets: all of it, or what the panel leaves.
glm::ivec2 frame_area(glm::ivec2 framebuffer, bool ui) {
  return ui ? glm::ivec2(std::max(framebuffer.x - int(kPanelWidth), 1), framebuffer.y) : framebuffer;
}

class Viewer {
 public:
  Viewer(const ViewerOptions& o, Scene scene)
      : options_(o),
        window_(scene.width + (ui() ? int(kPanelWidth) : 0), std::max(scene.height, ui() ? kPanelHeight : 0),
                "plumbago view: " + scene.source),
        session_(window_, std::move(scene)) {}

  void run() {
    for (int n = 1; !window_.should_close(); ++n) {
      bool busy = options_.frames > 0 || panels_.continuous || session_.stale();
      window_.begin_frame(busy ? 0 : 0.1);
      frame(options_.frames > 0 || panels_.continuous);
      if (n == options_.frames) {
        finish();
        return;
      }
      window_.present();
    }
  }

 private:
  bool ui() const { return !options_.no_ui; }

  void frame(bool always_render) {
    glm::ivec2 framebuffer = window_.framebuffer_size();
    Placement placed = place(image_.size(), frame_area(framebuffer, ui()));
    steer(session_, placed);
    if (ui()) panels_.draw(session_, framebuffer, kPanelWidth);
    if (session_.stale() || always_render) render();
    image_.draw(framebuffer, placed);
    window_.end_frame(ui());
    if (screenshot_key() || std::exchange(panels_.screenshot_wanted, false)) screenshot(panels_.screenshot_path);
  }

  void render() {
    if (!session_.render()) {
      if (options_.frames > 0) throw std::runtime_error("view: " + session_.error());
      return;
    }
    image_.show(session_.frame().color);
    panels_.timing.add(session_.frame(), session_.render_ms());
  }

  void screenshot(const std::string& path) { write_image(window_.read_pixels(), path); }

  void finish() {
    if (!options_.screenshot.empty()) screenshot(options_.screenshot);
  }

  const ViewerOptions& options_;
  Window window_;
  FrameImage image_;
  Session session_;
  Panels panels_;
};

}  // namespace

void run_viewer(const ViewerOptions& options) { Viewer(options, options.scene.load()).run(); }

}  // namespace plumbago
