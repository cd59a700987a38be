// The viewer's window: GLFW, an OpenGL 4.5 core context, Dear ImGui on top.
//
// Two GL contexts take turns on the viewer's one thread. The GPU pipeline keeps its own
// headless context (gpu::Context: EGL, Mesa's surfaceless platform on llvmpipe), exactly
// as `plumbago render` runs it, so the viewer draws the same pixels. The window's
// context only shows the frame: gpu::Renderer::render reads the frame back anyway, and
// the viewer uploads it to a texture of the window's context and blits it. Sharing
// objects between the two would need the same EGL display, which the surfaceless
// platform cannot give a window; on llvmpipe both live in host memory, so the copy costs
// about a millisecond. Under GLVND a thread may not make an EGL context current while a
// GLX one is (EGL_BAD_ACCESS), so each switch releases the other context first
// (GpuScope).
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <utility>
#include <vector>

#include "common/util/image.hpp"

struct GLFWwindow;

namespace plumbago {

class Window {
 public:
  // Throws std::runtime_error saying why when no window can be opened (no display, no
  // GL 4.5 core context).
  Window(int width, int height, const std::string& title);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  bool should_close() const;
  // Waits for input up to `timeout_s` (0: only polls), then starts an ImGui frame.
  void begin_frame(double timeout_s);
  // Ends the ImGui frame and draws its panels over what is drawn, unless `ui` is false.
  void end_frame(bool ui);
  void present();  // shows what was drawn
  glm::ivec2 framebuffer_size() const;
  // What the window shows now (the back buffer before end_frame presents it), RGB.
  Image read_pixels() const;
  // The files dropped on the window since the last call.
  std::vector<std::string> take_dropped() { return std::exchange(dropped_, {}); }
  // Makes the window's context current on this thread, or none.
  void make_current();
  void release();

 private:
  GLFWwindow* window_ = nullptr;
  std::vector<std::string> dropped_;
};

// While alive, the GPU pipeline's context is current instead of the window's.
class GpuScope {
 public:
  explicit GpuScope(Window& window);
  ~GpuScope();
  GpuScope(const GpuScope&) = delete;
  GpuScope& operator=(const GpuScope&) = delete;

 private:
  Window& window_;
};

}  // namespace plumbago
