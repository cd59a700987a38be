// The scene being viewed and edited, and the GPU renderer that draws it.
//
// gpu::Renderer reads a scene when it is made (the objects each pipeline draws, what the
// passes set up), so every change makes a new renderer. Its preprocessing (pencil
// textures, paper, curvature: most of the setup time on llvmpipe) is kept across a camera
// move and a change to a parameter no preprocessing step reads.
#pragma once

#include <memory>
#include <string>

#include "apps/viewer/window.hpp"
#include "common/frame.hpp"
#include "common/orbit.hpp"
#include "common/scene.hpp"
#include "gpu/pipeline.hpp"

namespace plumbago {

class Session {
 public:
  Session(Window& window, Scene scene);
  ~Session();  // frees the renderer in the pipeline's context

  const Scene& scene() const { return scene_; }

  // Each change makes the next render() draw anew.
  template <class Move>
  void move_camera(Move move) {  // move(OrbitCamera&)
    move(orbit_);
    camera_moved();
  }
  void set_param(const std::string& key, double value);
  void set_effect(const std::string& effect, bool on);
  void set_style(size_t object, Style style);

  bool stale() const { return stale_; }
  // Renders the current scene, making a new renderer first when it changed. False when
  // that failed (error() says why; the last good frame stays) until the next change.
  bool render();
  const Frame& frame() const { return frame_; }
  const std::string& error() const { return error_; }
  // The time the last new renderer took to make, preprocessing included, and the time
  // the last frame took to render and read back.
  double setup_ms() const { return setup_ms_; }
  double render_ms() const { return render_ms_; }

 private:
  void camera_moved();
  void restart();  // drops the preprocessing too
  void make_renderer();
  Window& window_;
  Scene scene_;
  OrbitCamera orbit_;
  std::unique_ptr<gpu::Renderer> renderer_;
  std::shared_ptr<const Preprocessed> preprocessed_;
  std::vector<std::string> preprocessed_passes_;  // the passes preprocessed_ was made for
  bool stale_ = true;
  Frame frame_;
  std::string error_;
  double setup_ms_ = 0, render_ms_ = 0;
};

}  // namespace plumbago
