#include "apps/viewer/session.hpp"

#include <algorithm>
#include <optional>
#include <utility>

#include "common/core/passes.hpp"
#include "common/sketchy/sketchy.hpp"

namespace plumbago {
namespace {

OrbitCamera scene_orbit(const Scene& scene) {
  glm::vec3 center;
  float radius;
  scene_bounds(scene, center, radius);
  return OrbitCamera(scene.camera, center, radius);
}

}  // namespace

Session::Session(Window& window, Scene scene)
    : window_(window),
      scene_(std::move(scene)),
      own_stroke_files_(scene_.stroke_files.size()),
      orbit_(scene_orbit(scene_)) {}

Session::~Session() {
  try {
    GpuScope gpu(window_);
    renderer_.reset();
  } catch (const std::exception&) {
    (void)renderer_.release();  // no pipeline context to free it in: left to the process's end
  }
}

void Session::camera_moved() {
  scene_.camera = orbit_.camera();
  if (scene_.lights_follow_camera) scene_.lights = default_lights(scene_.camera);
  moved_ = true;
}

void Session::replace(Scene scene, bool keep_camera) {
  scene.width = scene_.width;
  scene.height = scene_.height;
  scene_ = std::move(scene);
  own_stroke_files_ = scene_.stroke_files.size();
  show_drawn();
  if (!keep_camera) orbit_ = scene_orbit(scene_);
  camera_moved();
  restart();
}

void Session::set_param(const std::string& key, double value) {
  scene_.params.set(key, value);
  if (preprocessing_reads(preprocessed_passes_, key)) drop_preprocessed();
  stale_ = true;
}

void Session::set_effect(const std::string& effect, bool on) {
  std::erase(scene_.effects, effect);
  if (on) scene_.effects.push_back(effect);
  match_effects_to_styles(scene_);
  restart();
}

void Session::set_style(size_t object, Style style) {
  scene_.objects.at(object).style = style;
  match_effects_to_styles(scene_);
  restart();
}

void Session::set_drawn(std::vector<StrokeFile> files) {
  drawn_ = std::move(files);
  show_drawn();
  stale_ = true;
}

Scene Session::with_drawn(const std::vector<StrokeFile>& files) const {
  Scene s = scene_;
  s.stroke_files.resize(own_stroke_files_);
  s.stroke_files.insert(s.stroke_files.end(), files.begin(), files.end());
  set_drawn_examples(s);
  return s;
}

void Session::show_drawn() {
  scene_.stroke_files.resize(own_stroke_files_);
  scene_.stroke_files.insert(scene_.stroke_files.end(), drawn_.begin(), drawn_.end());
  set_drawn_examples(scene_);
}

void Session::keep_buffers(bool on) {
  if (on && !keep_buffers_) stale_ = true;
  keep_buffers_ = on;
}

void Session::restart() {
  drop_preprocessed();
  stale_ = true;
}

void Session::drop_preprocessed() {
  preprocessed_.reset();
  ++generation_;
}

void Session::start_preprocessing() {
  pending_passes_ = passes_for(scene_.effects, scene_.params);
  pending_generation_ = generation_;
  pending_since_ = Stopwatch();
  pending_ = std::async(std::launch::async, [scene = scene_, passes = pending_passes_] {
    return std::make_shared<const Preprocessed>(preprocess(scene, passes));
  });
}

bool Session::preprocessed_ready() {
  if (preprocessed_ && passes_for(scene_.effects, scene_.params) == preprocessed_passes_) return true;
  if (!pending_.valid()) start_preprocessing();
  if (pending_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return false;
  last_preprocessing_s_ = preprocessing_s();
  std::shared_ptr<const Preprocessed> made = pending_.get();
  if (pending_generation_ != generation_ || pending_passes_ != passes_for(scene_.effects, scene_.params)) {
    start_preprocessing();  // made for an earlier state of the scene
    return false;
  }
  preprocessed_ = std::move(made);
  preprocessed_passes_ = pending_passes_;
  return true;
}

void Session::make_renderer() {
  Stopwatch watch;
  renderer_.reset();
  renderer_ = std::make_unique<gpu::Renderer>(scene_, preprocessed_);
  renderer_->follow_every_frame();  // the orbit's views follow each other: coherent strokes carry
  setup_ms_ = watch.ms();
}

bool Session::render() {
  std::optional<GpuScope> gpu;
  try {
    if (stale_ && !preprocessed_ready()) return false;
    gpu.emplace(window_);
    if (std::exchange(stale_, false))
      make_renderer();
    else if (moved_ && renderer_)
      renderer_->camera_moved();
    moved_ = false;
    if (!renderer_) return false;
    Stopwatch watch;
    frame_ = renderer_->render(FrameOptions{keep_buffers_});
    render_ms_ = watch.ms();
    error_.clear();
    return true;
  } catch (const std::exception& e) {
    if (gpu) renderer_.reset();  // in its own context, or (none to be had) left alone
    stale_ = moved_ = false;     // tried again after the next change
    error_ = e.what();
    return false;
  }
}

}  // namespace plumbago
