// The headless GL 4.5 core context of the GPU backend.
//  - EGL (default): an NVIDIA device through EGL_EXT_platform_device when there is one,
//    else Mesa's surfaceless platform (llvmpipe on a machine without a GPU).
//  - OSMesa (-DPLUMBAGO_GL=osmesa): Mesa's off-screen library, same GPU code.
// KHR_debug messages are collected; check_errors() throws on any GL error reported since
// the last check, naming what was running.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace plumbago::gpu {

class Context {
 public:
  // The process-wide context, created and made current on first use. Throws
  // std::runtime_error saying what is missing when no GL 4.5 core context can be had.
  static Context& get();

  std::string renderer() const;                              // GL_RENDERER
  std::string version() const;                               // GL_VERSION
  const std::string& platform() const { return platform_; }  // "egl-device", "egl-surfaceless", "osmesa"

  // Throws std::runtime_error if GL reported an error (glGetError or a KHR_debug error
  // message) since the last call. `what` names the stage in the message.
  void check_errors(const std::string& what);
  // Debug messages of any severity collected since the last call.
  std::vector<std::string> take_messages();

  // Makes the context current on the calling thread again, or leaves the thread with no
  // current context (release), for a program that draws into a window's context too
  // (plumbago view). Throws std::runtime_error when the platform refuses.
  void make_current();
  void release();

  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  struct Impl;

 private:
  Context();
  std::string platform_;  // set while impl_ is made: declared first
  std::unique_ptr<Impl> impl_;
  std::vector<std::string> messages_;
  std::vector<std::string> errors_;
  friend void debug_callback_sink(Context&, bool is_error, std::string message);
};

}  // namespace plumbago::gpu
