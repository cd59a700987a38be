// The scene being viewed and edited, and the GPU renderer that draws it.
//
// gpu::Renderer reads a scene when it is made (the objects each pipeline draws, what the
// passes set up), so every change but a camera move makes a new renderer; a camera move keeps
// it (gpu::Renderer::camera_moved). Its preprocessing (pencil
// textures, paper, curvature: most of the setup time on llvmpipe; CPU only) is kept
// across a camera move and a change to a parameter no preprocessing step reads, and made
// anew in a worker thread: the last frame stays until it is done.
#pragma once

#include <future>
#include <memory>
#include <string>

#include "apps/viewer/window.hpp"
#include "common/core/frame.hpp"
#include "common/core/preprocess.hpp"
#include "common/scene/orbit.hpp"
#include "common/scene/scene.hpp"
#include "gpu/core/pipeline.hpp"

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
  // Another scene in this one's size: with this camera (a file edited on disk) or its own.
  void replace(Scene scene, bool keep_camera);
  void fail(const std::string& why) { error_ = why; }  // shown as error() until a frame renders
  void set_param(const std::string& key, double value);
  void set_effect(const std::string& effect, bool on);
  void set_style(size_t object, Style style);
  // The stroke files drawn in the viewer (apps/viewer/drawing.hpp), shown after the scene's
  // own, kept across a replace(): a new renderer projects them; preprocessing stays.
  void set_drawn(std::vector<StrokeFile> files);
  // The scene as it would be with `files` drawn instead.
  Scene with_drawn(const std::vector<StrokeFile>& files) const;

  // Whether frames keep their intermediate buffers (Frame::buffers: the stage view).
  void keep_buffers(bool on);
  bool stale() const { return stale_ || moved_; }
  // Whether preprocessing runs in the background; how long it has, and what the last one
  // took (0 before the first).
  bool preprocessing() const { return pending_.valid(); }
  double preprocessing_s() const { return pending_since_.ms() / 1000; }
  double last_preprocessing_s() const { return last_preprocessing_s_; }
  // Renders the current scene, making a new renderer first when it changed. False when
  // that failed (error() says why; the last good frame stays) until the next change, or
  // while preprocessing for it runs (stale() stays true).
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
  void drop_preprocessed();
  // Whether preprocessed_ is there for the current scene; else starts making it (or
  // takes what the worker made) and says false.
  bool preprocessed_ready();
  void start_preprocessing();
  void make_renderer();
  Window& window_;
  void show_drawn();
  Scene scene_;
  size_t own_stroke_files_;  // the scene's, before the drawn ones
  std::vector<StrokeFile> drawn_;
  OrbitCamera orbit_;
  std::unique_ptr<gpu::Renderer> renderer_;
  std::shared_ptr<const Preprocessed> preprocessed_;
  std::vector<std::string> preprocessed_passes_;              // the passes preprocessed_ was made for
  long generation_ = 0;                                       // counts the drops of preprocessed_
  std::future<std::shared_ptr<const Preprocessed>> pending_;  // made in the worker
  std::vector<std::string> pending_passes_;
  long pending_generation_ = 0;
  Stopwatch pending_since_;
  double last_preprocessing_s_ = 0;
  bool stale_ = true;
  bool moved_ = false;  // the camera moved since the last frame (the renderer kept)
  bool keep_buffers_ = false;
  Frame frame_;
  std::string error_;
  double setup_ms_ = 0, render_ms_ = 0;
};

}  // namespace plumbago
