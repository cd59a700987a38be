#include "apps/viewer/session.hpp"

#include <algorithm>
#include <optional>
#include <utility>

#include "common/passes.hpp"

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
    : window_(window), scene_(std::move(scene)), orbit_(scene_orbit(scene_)) {}

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
  stale_ = true;
}

void Session::set_param(const std::string& key, double value) {
  scene_.params.set(key, value);
  if (preprocessing_reads(preprocessed_passes_, key)) preprocessed_.reset();
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

void Session::restart() {
  preprocessed_.reset();
  stale_ = true;
}

void Session::make_renderer() {
  Stopwatch watch;
  renderer_.reset();
  std::vector<std::string> passes = passes_for(scene_.effects, scene_.params);
  if (passes != preprocessed_passes_) preprocessed_.reset();
  renderer_ = std::make_unique<gpu::Renderer>(scene_, preprocessed_);
  preprocessed_ = renderer_->preprocessed();
  preprocessed_passes_ = passes;
  setup_ms_ = watch.ms();
}

bool Session::render() {
  std::optional<GpuScope> gpu;
  try {
    gpu.emplace(window_);
    if (std::exchange(stale_, false)) make_renderer();
    if (!renderer_) return false;
    Stopwatch watch;
    frame_ = renderer_->render();
    render_ms_ = watch.ms();
    error_.clear();
    return true;
  } catch (const std::exception& e) {
    if (gpu) renderer_.reset();  // in its own context, or (none to be had) left alone
    stale_ = false;             // tried again after the next change
    error_ = e.what();
    return false;
  }
}

}  // namespace plumbago
