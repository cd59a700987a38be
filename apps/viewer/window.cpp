#include "apps/viewer/window.hpp"

#include "gpu/gl/gl.hpp"  // before GLFW, which then includes no GL header of its own
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <stdexcept>

#include "gpu/gl/context.hpp"

namespace plumbago {
namespace {

std::string glfw_error;  // the last message GLFW reported

void on_glfw_error(int, const char* message) { glfw_error = message; }

[[noreturn]] void cannot_open(const std::string& what) {
  throw std::runtime_error("view: cannot open a window: " + what + ": " + glfw_error +
                           " (a display is needed: set DISPLAY, or run under xvfb-run)");
}

GLFWwindow* open_window(int width, int height, const std::string& title) {
  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit()) cannot_open("GLFW cannot start");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  GLFWwindow* w = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!w) {
    glfwTerminate();
    cannot_open("no OpenGL 4.5 core window");
  }
  return w;
}

void on_drop(GLFWwindow* window, int count, const char** paths) {
  auto* dropped = static_cast<std::vector<std::string>*>(glfwGetWindowUserPointer(window));
  dropped->insert(dropped->end(), paths, paths + count);
}

}  // namespace

Window::Window(int width, int height, const std::string& title) : window_(open_window(width, height, title)) {
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);
  glfwSetWindowUserPointer(window_, &dropped_);
  glfwSetDropCallback(window_, on_drop);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working folder
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 450 core");
}

Window::~Window() {
  make_current();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool Window::should_close() const { return glfwWindowShouldClose(window_); }

void Window::begin_frame(double timeout_s) {
  if (timeout_s > 0)
    glfwWaitEventsTimeout(timeout_s);
  else
    glfwPollEvents();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void Window::end_frame(bool ui) {
  ImGui::Render();
  if (ui) ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void Window::present() { glfwSwapBuffers(window_); }

glm::ivec2 Window::framebuffer_size() const {
  glm::ivec2 size;
  glfwGetFramebufferSize(window_, &size.x, &size.y);
  return size;
}

Image Window::read_pixels() const {
  glm::ivec2 size = framebuffer_size();
  Image img(size.x, size.y, 3);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size.x, size.y, GL_RGB, GL_FLOAT, img.data.data());
  return img;
}

void Window::make_current() { glfwMakeContextCurrent(window_); }
void Window::release() { glfwMakeContextCurrent(nullptr); }

GpuScope::GpuScope(Window& window) : window_(window) {
  window_.release();
  try {
    gpu::Context::get().make_current();
  } catch (const std::exception&) {
    window_.make_current();
    throw;
  }
}

GpuScope::~GpuScope() {
  try {
    gpu::Context::get().release();
  } catch (const std::exception&) {  // the window's context is made current regardless
  }
  window_.make_current();
}

}  // namespace plumbago
