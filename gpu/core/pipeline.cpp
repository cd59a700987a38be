#include "gpu/core/pipeline.hpp"

#include <optional>
#include <stdexcept>

#include "common/core/passes.hpp"
#include "common/core/preprocess.hpp"
#include "common/sketchy/sketchy.hpp"
#include "common/strokes/id_image.hpp"
#include "common/strokes/silhouette_chains.hpp"
#include "common/strokes/stroke.hpp"
#include "common/strokes/visibility.hpp"
#include "gpu/core/stage.hpp"
#include "gpu/gl/context.hpp"
#include "gpu/gl/timer.hpp"
#include "gpu/strokes/window_paths.hpp"

namespace plumbago::gpu {

struct Renderer::State {
  std::vector<std::string> all;
  std::shared_ptr<const Preprocessed> pre;
  GpuFrame frame;
  std::vector<const GpuPassDef*> plan;
  std::vector<std::unique_ptr<GpuPass>> passes;  // one per planned pass
  PassTimer timer;

  State(const Scene& scene, std::shared_ptr<const Preprocessed> made)
      : all(passes_for(scene.effects, scene.params)),
        pre(made ? std::move(made) : std::make_shared<const Preprocessed>(preprocess(scene, all))),
        frame(scene, *pre, frame_stages(all)),
        plan(plan_passes(frame.stages, frame.config())) {
    for (const GpuPassDef* def : plan) passes.push_back(make_checked(*def, frame));
  }

  // A table the frame wrote, read back; none where its stage did not run.
  std::optional<Image> download(plumbago::Buffer table, int channels) const {
    const Texture* t = frame.get(maybe(table));
    return t ? std::optional(download_texture(*t, channels)) : std::nullopt;
  }

  void run_frame() {
    frame.data.clear();  // CPU data of the frame (the window lines ...) is made anew each frame
    for (size_t i = 0; i < plan.size(); ++i) {
      const std::string name = plan[i]->name();
      timer.begin(name);
      run_checked(*plan[i], *passes[i], frame);
      timer.end();
      Context::get().check_errors(name);
    }
    glFinish();
    frame.last_drawn = frame.scene.frame;
  }

  // Every buffer the frame's stages declare (common/core/stage.hpp dumped_buffers).
  std::map<std::string, Image> dump() {
    std::map<std::string, Image> all_buffers, out;
    for (size_t i = 0; i < plan.size(); ++i) passes[i]->dump(frame, plan[i]->stages, all_buffers);
    for (const std::string& name : dumped_buffers(frame.stages, frame.config())) {
      auto it = all_buffers.find(name);
      if (it == all_buffers.end())
        throw std::logic_error("GPU: stage '" + stage_of(name).name + "' did not write '" + name + "'");
      out[name] = std::move(it->second);
    }
    return out;
  }
};

Renderer::Renderer(const Scene& scene, std::shared_ptr<const Preprocessed> preprocessed) {
  Context& context = Context::get();  // before any GL call
  state_ = std::make_unique<State>(scene, std::move(preprocessed));
  context.check_errors("setting up the GPU renderer");
}

Renderer::~Renderer() = default;

void Renderer::follow_every_frame() { state_->frame.every_frame_follows = true; }

void Renderer::camera_moved() {
  GpuFrame& f = state_->frame;
  f.camera_moved();
  for (auto& pass : state_->passes) pass->moved(f, f.scene.lights_follow_camera);
  Context::get().check_errors("moving the GPU renderer's camera");
}

double Renderer::render_frame(Frame& timing) {
  Stopwatch watch;
  ThreadClock host;
  size_t read_before = bytes_read_back();
  state_->frame.whole_lines = false;
  state_->run_frame();
  double ms = watch.ms();
  timing.host_ms = host.ms();
  timing.readback_bytes = bytes_read_back() - read_before;
  timing.ran = state_->timer.results();
  return ms;
}

GBufferChannels Renderer::frame_channels(const std::string& stage) const {
  GpuFrame& f = state_->frame;
  bool dump = f.dump;
  f.dump = false;
  GBufferChannels c = f.gbuffer_channels(stage);
  f.dump = dump;
  return c;
}

std::shared_ptr<const Preprocessed> Renderer::preprocessed() const { return state_->pre; }

const GpuFrame& Renderer::frame() const { return state_->frame; }

Image Renderer::color() const {
  std::string color = frame_color_buffer(state_->frame.stages);  // none without effects: the blank page
  const Scene& scene = state_->frame.scene;
  return color.empty() ? Image(scene.width, scene.height, 3, 1.0f)
                       : download_texture(state_->frame.texture_named(color), 3);
}

Frame Renderer::render(const FrameOptions& options) {
  Frame frame;
  state_->frame.dump = options.keep_buffers;
  state_->frame.whole_lines = true;
  state_->run_frame();
  frame.ran = state_->pre->ran;  // made once, listed with every frame that uses it
  for (const PassTime& t : state_->timer.results()) frame.ran.push_back(t);
  Stopwatch readback;
  frame.color = color();
  frame.ran.push_back({"readback", readback.ms()});
  if (options.keep_buffers) {
    frame.buffers = state_->dump();
    frame.lines = kept(state_->frame.data.find(kWindowLines));
    frame.visibility = kept(state_->frame.data.find(kVisibleRuns));
  }
  const WindowLines* lines = state_->frame.data.find(kWindowLines);
  const Visibility* runs = state_->frame.data.find(kVisibleRuns);  // a dump's
  const RunTables* tables = state_->frame.get(maybe(kRunTables));
  std::optional<Visibility> read;  // else read back, after the frame, from where its passes left them
  if (!runs && tables && lines) runs = &read.emplace(read_runs(*tables, *lines));
  frame.counts = stroke_counts(lines, runs);
  std::optional<Image> facing = state_->download(kSegmentFacing, 1), chains = state_->download(kChains, 4);
  frame.counts.merge(silhouette_counts(facing ? &*facing : nullptr, chains ? &*chains : nullptr));
  Context::get().check_errors("reading back the frame");
  return frame;
}

}  // namespace plumbago::gpu
