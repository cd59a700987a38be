#include "gpu/pipeline.hpp"

#include <functional>
#include <map>
#include <stdexcept>

#include "common/compose.hpp"
#include "common/passes.hpp"
#include "common/preprocess.hpp"
#include "common/lights.hpp"
#include "gpu/compose.hpp"
#include "gpu/contour_light.hpp"
#include "gpu/multi_contour.hpp"
#include "gpu/context.hpp"
#include "gpu/edge_detect.hpp"
#include "gpu/gbuffer.hpp"
#include "gpu/timer.hpp"

namespace plumbago::gpu {

struct Renderer::State {
  const Scene& scene;
  std::vector<std::string> passes = passes_for(scene.effects);
  std::vector<std::string> stages = frame_stages(passes);
  Preprocessed pre = preprocess(scene, passes);
  ContourInputs contour_inputs = pre.offset_grids.empty() ? ContourInputs{}
                                 : upload_contour_inputs(pre.offset_grids, pre.contour_texture, pre.texture_shifts);
  GBufferPass gbuffer_pass{scene};
  EdgeDetectPass edge_pass;
  ContourLightPass contour_light_pass;
  MultiContourPass multi_contour_pass;
  ComposePass compose_pass;
  GBufferTargets gbuffer = make_gbuffer_targets(scene.width, scene.height,
                                                scene.params.get<GBufferParams>().normal_format);
  Texture contour_darkness = make_texture(scene.width, scene.height, GL_R32F);
  Texture lit_contour_darkness = make_texture(scene.width, scene.height, GL_R32F);
  Texture multi_contour_darkness = make_texture(scene.width, scene.height, GL_R32F);
  Texture color = make_texture(scene.width, scene.height, GL_RGBA8);
  PassTimer timer;

  explicit State(const Scene& s) : scene(s) {}

  void run(const std::string& pass) {
    if (pass == "gbuffer") {
      gbuffer_pass.render(scene, gbuffer);
    } else if (pass == "edge_detect") {
      edge_pass.run(gbuffer, scene.params.get<EdgeDetectParams>(), contour_darkness);
    } else if (pass == "contour_light") {
      contour_light_pass.run(contour_darkness, gbuffer, view_space_lights(scene), scene.params.get<ContourLightParams>(),
                             lit_contour_darkness);
    } else if (pass == "multi_contour") {
      multi_contour_pass.run(lit_contour_darkness, contour_inputs, scene.params.get<ContourParams>(),
                             multi_contour_darkness);
    } else if (pass == "compose") {
      compose_pass.run(multi_contour_darkness, scene.params.get<ComposeParams>(), color);
    } else {
      throw std::runtime_error("pass '" + pass + "' is not implemented on the GPU backend");
    }
  }

  void run_frame() {
    for (const std::string& pass : stages) {
      timer.begin(pass);
      run(pass);
      timer.end();
      Context::get().check_errors(pass);
    }
    glFinish();
  }
};

Renderer::Renderer(const Scene& scene) {
  Context& context = Context::get();  // before any GL call
  state_ = std::make_unique<State>(scene);
  context.check_errors("setting up the GPU renderer");
}

Renderer::~Renderer() = default;

double Renderer::render_frame(Frame& timing) {
  Stopwatch watch;
  state_->run_frame();
  double ms = watch.ms();
  timing.ran = state_->timer.results();
  return ms;
}

Frame Renderer::render(const FrameOptions& options) {
  Frame frame;
  state_->run_frame();
  frame.ran = state_->pre.ran;  // once per Renderer, listed with every frame it renders
  for (const PassTime& t : state_->timer.results()) frame.ran.push_back(t);
  Stopwatch readback;
  frame.color = download_texture(state_->color, 3);
  frame.ran.push_back({"readback", readback.ms()});
  if (options.keep_buffers) {
    add_gbuffer_buffers(download_gbuffer(state_->gbuffer), frame.buffers);
    frame.buffers["edge_detect.contour_darkness"] = download_texture(state_->contour_darkness, 1);
    frame.buffers["contour_light.lit_contour_darkness"] = download_texture(state_->lit_contour_darkness, 1);
    frame.buffers["multi_contour.contour_darkness"] = download_texture(state_->multi_contour_darkness, 1);
    frame.buffers["compose.color"] = frame.color;
  }
  Context::get().check_errors("reading back the frame");
  return frame;
}

}  // namespace plumbago::gpu
