#include "apps/viewer/viewer.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>  // key codes only
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "apps/viewer/drawing_tool.hpp"
#include "apps/viewer/file_watch.hpp"
#include "apps/viewer/frame_image.hpp"
#include "apps/viewer/inspection.hpp"
#include "apps/viewer/panels.hpp"
#include "apps/viewer/script.hpp"
#include "apps/viewer/session.hpp"
#include "apps/viewer/window.hpp"
#include "common/util/output_file.hpp"

namespace plumbago {
namespace {

constexpr float kPanelWidth = 440;  // pixels right of the frame
constexpr int kPanelHeight = 720;   // the window's least height with the panel
constexpr float kDegreesPerPixel = 0.4f;
constexpr float kZoomPerNotch = 0.9f;

// Mouse and keys over the frame (not over the panel): left drag orbits (unless it draws),
// right or middle drag pans, the wheel zooms; R: the scene's camera, F: frame the scene.
void steer(Session& session, const Placement& frame, bool drawing) {
  const ImGuiIO& io = ImGui::GetIO();
  glm::vec2 d(io.MouseDelta.x, io.MouseDelta.y);
  bool moved = d != glm::vec2(0);
  if (!io.WantCaptureMouse && moved && io.MouseDown[ImGuiMouseButton_Left] && !drawing)
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

void write_json(const std::string& path, const nlohmann::json& j) {
  OutputFile out(path);
  std::ofstream(out.temporary_path()) << j.dump(2) << '\n';
  out.commit();
}

// The frame point under the cursor (pixels, origin bottom-left: docs/conventions.md), or
// -1s off the frame or over the panel.
glm::dvec2 point_under_cursor(const Placement& p, glm::ivec2 framebuffer, glm::ivec2 frame) {
  const ImGuiIO& io = ImGui::GetIO();
  glm::dvec2 scale(io.DisplayFramebufferScale.x, io.DisplayFramebufferScale.y);
  glm::dvec2 at(io.MousePos.x * scale.x, double(framebuffer.y) - io.MousePos.y * scale.y);
  glm::dvec2 f = (at - glm::dvec2(p.origin)) / glm::max(glm::dvec2(p.size), glm::dvec2(1)) * glm::dvec2(frame);
  bool off = f.x < 0 || f.y < 0 || f.x >= frame.x || f.y >= frame.y || io.WantCaptureMouse;
  return off ? glm::dvec2(-1) : f;
}

// The frame pixel under the cursor (row 0 at the bottom), or -1s off the frame.
glm::ivec2 pixel_under_cursor(const Placement& p, glm::ivec2 framebuffer, glm::ivec2 frame) {
  return glm::ivec2(glm::floor(point_under_cursor(p, framebuffer, frame)));
}

class Viewer {
 public:
  Viewer(const ViewerOptions& o, Scene scene)
      : options_(o),
        script_(o.script.empty() ? Script() : Script(o.script)),
        window_(scene.width + (ui() ? int(kPanelWidth) : 0), std::max(scene.height, ui() ? kPanelHeight : 0),
                "plumbago view: " + scene.source),
        session_(window_, std::move(scene)) {
    watch_.watch(session_.scene().source);
  }

  void run() {
    for (int n = 1; !window_.should_close(); ++n) {
      // Whether the panel this frame draws shows the final state (it draws before the frame renders).
      const bool settled = !session_.stale() && !session_.preprocessing();
      window_.begin_frame(wait_s());
      frame(options_.frames > 0 || panels_.continuous);
      if (options_.frames > 0 && n >= options_.frames && script_.done() && settled && !session_.stale()) {
        finish();
        return;
      }
      window_.present();
    }
  }

 private:
  bool ui() const { return !options_.no_ui; }

  // How long the next frame waits for input: a little while a worker computes, not at
  // all while there is drawing to do.
  double wait_s() const {
    if (inspect_.check.running() || session_.preprocessing()) return 0.01;
    return session_.stale() || panels_.continuous || options_.frames > 0 ? 0 : 0.1;
  }

  void frame(bool always_render) {
    if (watch_.changed()) open(session_.scene().source, true);
    for (const std::string& path : window_.take_dropped()) open(path, false);
    run_script();
    glm::ivec2 framebuffer = window_.framebuffer_size();
    Placement area = place(image_.size(), frame_area(framebuffer, ui()));
    if (ui())
      drawing_.handle_input(point_under_cursor(area, framebuffer, image_.size()), panels_.left_drag,
                            panels_.draw_settings);
    steer(session_, area, ui() && panels_.left_drag != LeftDrag::Orbit);
    poll_check();
    if (ui()) panels_.draw(session_, inspect_, drawing_, framebuffer, kPanelWidth);
    if (session_.stale() || always_render) render();
    show();
    Placement placed = place(image_.size(), frame_area(framebuffer, ui()));  // the first frame's size is known now
    if (ui()) readout(placed, framebuffer);
    image_.draw(framebuffer, placed);
    window_.end_frame(ui());
    if (screenshot_key() || std::exchange(panels_.screenshot_wanted, false)) screenshot(panels_.screenshot_path);
    if (!script_shot_.empty()) screenshot(std::exchange(script_shot_, ""));
  }

  void render() {
    if (!session_.render()) {
      if (options_.frames > 0 && !session_.error().empty()) throw std::runtime_error("view: " + session_.error());
      return;
    }
    ++rendered_;
    panels_.timing.add(session_.frame(), session_.render_ms());
  }

  // The frame area anew when the frame or what to show of it changed.
  void show() {
    auto key = std::make_tuple(rendered_, inspect_.stage.buffer(), inspect_.heatmap, inspect_.check.results().size());
    if (rendered_ == 0 || key == shown_) return;
    shown_ = key;
    try {
      image_.show(inspect_.image(session_.frame()));
    } catch (const std::invalid_argument&) {  // the buffer went with a change of effects
      inspect_.stage.select("");
      session_.keep_buffers(false);
      image_.show(session_.frame().color);
    }
  }

  void readout(const Placement& placed, glm::ivec2 framebuffer) {
    glm::ivec2 pixel = pixel_under_cursor(placed, framebuffer, image_.size());
    if (inspect_.heatmap >= 0 || rendered_ == 0) return;
    std::string text = inspect_.stage.readout(session_.frame(), pixel);
    if (!text.empty()) ImGui::SetTooltip("%s", text.c_str());
  }

  // `source` (scene or mesh file) in place of the scene, watched from now on.
  void open(const std::string& source, bool keep_camera) {
    try {
      session_.replace(open_source(source, session_.scene()), keep_camera);
      watch_.watch(source);
      ++reloads_;
    } catch (const std::exception& e) {         // a file half written, a mesh that is no mesh
      session_.fail(source + ": " + e.what());  // the last frame stays; the next edit may fix it
    }
  }

  void poll_check() {
    if (!inspect_.check.running()) return;
    GpuScope gpu(window_);
    inspect_.check.poll();
  }

  // Applies the script's actions up to one that must wait: for the changes before it to
  // draw (what looks at the frame), for the reference check or a reload; and stops after
  // a screenshot, written when this frame drew.
  void run_script() {
    static const std::set<std::string> look = {"stage", "check", "heatmap", "save", "screenshot"};
    while (!script_.done() && script_shot_.empty()) {
      if (session_.stale() && look.count(script_.next().key)) return;
      try {
        if (!apply(script_.next())) return;
      } catch (const std::exception& e) {
        throw std::runtime_error(script_.where() + e.what());
      }
      script_.advance();
    }
  }

  bool apply(const ScriptAction& a) {  // false: to be applied again at the next frame
    if (a.key == "set")
      for (const auto& [key, value] : a.arg.items()) session_.set_param(key, param_value(key, value));
    if (a.key == "effect")
      for (const auto& [name, on] : a.arg.items()) session_.set_effect(name, on.get<bool>());
    if (a.key == "orbit")
      session_.move_camera([&](OrbitCamera& o) { o.orbit(a.arg[0].get<float>(), a.arg[1].get<float>()); });
    if (a.key == "stage") select_stage(a.arg.get<std::string>());
    if (a.key == "heatmap") inspect_.heatmap = int(check_result(a.arg.get<std::string>()));
    if (a.key == "save") save_scene(session_.scene(), a.arg.get<std::string>());  // refuses unsaved strokes
    if (a.key == "screenshot") script_shot_ = a.arg.get<std::string>();
    if (a.key == "reload") return std::exchange(reloads_, 0) > 0;
    if (a.key == "draw") drawing_.draw(draw_request(a.arg));
    if (a.key == "undo" && !drawing_.undo()) throw std::invalid_argument("nothing drawn to undo");
    if (a.key == "redo" && !drawing_.redo()) throw std::invalid_argument("nothing undone to redo");
    if (a.key == "save_strokes") drawing_.save(a.arg.get<std::string>());
    if (a.key == "erase" && !drawing_.erase_at({a.arg[0].get<double>(), a.arg[1].get<double>()}))
      throw std::invalid_argument("no drawn decal or hatch within " + std::to_string(int(DrawingTool::kEraserPx)) +
                                  " px");
    return a.key != "check" || check(a.arg.get<std::string>());
  }

  // The stage view of `buffer`, refused now (not at the next frame) when the frame has none.
  void select_stage(const std::string& buffer) {
    inspect_.stage.select(buffer);
    inspect_.heatmap = -1;
    session_.keep_buffers(!buffer.empty());
    if (!session_.render()) throw std::runtime_error(session_.error());
    ++rendered_;
    inspect_.stage.image(session_.frame());
  }

  // Starts the check, then (at a later frame) writes its report when it is done.
  bool check(const std::string& report) {
    if (!std::exchange(checking_, true)) inspect_.check.start(session_.scene());
    if (inspect_.check.running()) return false;
    checking_ = false;
    if (!inspect_.check.error().empty()) throw std::runtime_error(inspect_.check.error());
    if (!report.empty()) write_json(report, inspect_.check.report());
    return true;
  }

  size_t check_result(const std::string& name) const {
    const auto& results = inspect_.check.results();
    for (size_t i = 0; i < results.size(); ++i)
      if (results[i].name == name) return i;
    throw std::invalid_argument("no checked stage '" + name + "' (a check action first; compare --json names them)");
  }

  void screenshot(const std::string& path) { write_image(window_.read_pixels(), path); }

  void finish() {
    if (!options_.screenshot.empty()) screenshot(options_.screenshot);
  }

  const ViewerOptions& options_;
  Script script_;
  Window window_;
  FrameImage image_;
  Session session_;
  Panels panels_;
  Inspection inspect_;
  long rendered_ = 0;  // frames rendered
  std::tuple<long, std::string, int, size_t> shown_;
  std::string script_shot_;  // a screenshot the script asked for, written after this frame
  bool checking_ = false;    // the script's check action is under way
  FileWatch watch_;
  DrawingTool drawing_{session_, window_};
  int reloads_ = 0;  // files opened since the script last waited for one
};

}  // namespace

void run_viewer(const ViewerOptions& options) { Viewer(options, options.scene.load()).run(); }

}  // namespace plumbago
