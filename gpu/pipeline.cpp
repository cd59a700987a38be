#include "gpu/pipeline.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <stdexcept>

#include "common/compose.hpp"
#include "common/paper.hpp"
#include "common/pencil_interior.hpp"
#include "common/passes.hpp"
#include "common/preprocess.hpp"
#include "common/lights.hpp"
#include "gpu/compose.hpp"
#include "gpu/multi_contour.hpp"
#include "gpu/pencil_interior.hpp"
#include "gpu/context.hpp"
#include "gpu/edge_detect.hpp"
#include "gpu/gbuffer.hpp"
#include "gpu/timer.hpp"

namespace plumbago::gpu {

namespace {

// Stages that one GPU pass computes together (one shader, one output each), so that a
// frame reads its inputs once: "a+b" replaces a followed by b.
std::vector<std::string> fused(const std::vector<std::string>& stages) {
  static const std::vector<std::pair<std::string, std::string>> pairs = {{"edge_detect", "contour_light"},
                                                                         {"interior_intensity", "pencil_interior"}};
  std::vector<std::string> out;
  for (size_t i = 0; i < stages.size(); ++i) {
    bool joined = false;
    for (const auto& [a, b] : pairs)
      if (stages[i] == a && i + 1 < stages.size() && stages[i + 1] == b) {
        out.push_back(a + "+" + b);
        joined = true;
        ++i;
        break;
      }
    if (!joined) out.push_back(stages[i]);
  }
  return out;
}

}  // namespace

struct Renderer::State {
  const Scene& scene;
  std::vector<std::string> passes = passes_for(scene.effects);
  std::vector<std::string> stages = frame_stages(passes);
  std::vector<std::string> gpu_passes = fused(stages);
  Preprocessed pre = preprocess(scene, passes);
  ContourInputs contour_inputs = pre.offset_grids.empty() ? ContourInputs{}
                                 : upload_contour_inputs(pre.offset_grids, pre.contour_texture, pre.texture_shifts);
  Texture pencil_stack = pre.pencil_stack.empty() ? make_texture(1, 1, GL_R32F) : upload_texture_3d(pre.pencil_stack, GL_R32F);
  Texture paper_normal = pre.paper.normal.empty() ? make_texture(1, 1, GL_RGBA32F) : upload_texture(pre.paper.normal, GL_RGBA32F);
  Texture paper_color = pre.paper.color.empty() ? make_texture(1, 1, GL_RGBA32F) : upload_texture(pre.paper.color, GL_RGBA32F);
  GBufferPass gbuffer_pass{scene, pre.curvature};
  EdgeDetectPass edge_pass;
  MultiContourPass multi_contour_pass;
  PencilInteriorPass pencil_interior_pass;
  ComposePass compose_pass;
  GBufferTargets gbuffer = make_gbuffer_targets(scene.width, scene.height,
                                                scene.params.get<GBufferParams>().normal_format);
  Texture contour_darkness = make_texture(scene.width, scene.height, GL_R32F);
  Texture lit_contour_darkness = make_texture(scene.width, scene.height, GL_R32F);
  Texture multi_contour_darkness = make_texture(scene.width, scene.height, GL_R32F);
  Texture interior_intensity = make_texture(scene.width, scene.height, GL_R32F);
  Texture interior_darkness = make_texture(scene.width, scene.height, GL_R32F);
  Texture color = make_texture(scene.width, scene.height, GL_RGBA8);
  PassTimer timer;
  GBufferChannels gbuffer_channels = channels_read_by(stages, scene);  // all of them for a dump

  explicit State(const Scene& s) : scene(s) {}

  bool ran(const char* stage) const { return std::find(stages.begin(), stages.end(), stage) != stages.end(); }

  void run(const std::string& pass) {
    if (pass == "gbuffer") {
      gbuffer_pass.render(scene, gbuffer, gbuffer_channels);
    } else if (pass == "edge_detect+contour_light") {
      edge_pass.run(gbuffer, scene.params.get<EdgeDetectParams>(), view_space_lights(scene),
                    scene.params.get<ContourLightParams>(), contour_darkness, lit_contour_darkness);
    } else if (pass == "multi_contour") {
      multi_contour_pass.run(lit_contour_darkness, contour_inputs, scene.params.get<ContourParams>(),
                             multi_contour_darkness);
    } else if (pass == "interior_intensity+pencil_interior") {
      pencil_interior_pass.run(gbuffer, view_space_lights(scene), pencil_stack, paper_normal,
                               interior_options(scene.effects), scene.params.get<InteriorParams>(),
                               scene.params.get<PaperParams>().mu_p, interior_darkness, interior_intensity);
    } else if (pass == "compose") {
      compose_pass.run(multi_contour_darkness, ran("multi_contour"), interior_darkness, ran("pencil_interior"),
                       paper_color, !pre.paper.color.empty(), scene.params.get<ComposeParams>(), color);
    } else {
      throw std::runtime_error("pass '" + pass + "' is not implemented on the GPU backend");
    }
  }

  void run_frame() {
    for (const std::string& pass : gpu_passes) {
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
  state_->gbuffer_channels = options.keep_buffers ? GBufferChannels{} : channels_read_by(state_->stages, state_->scene);
  state_->run_frame();
  frame.ran = state_->pre.ran;  // once per Renderer, listed with every frame it renders
  for (const PassTime& t : state_->timer.results()) frame.ran.push_back(t);
  Stopwatch readback;
  frame.color = download_texture(state_->color, 3);
  frame.ran.push_back({"readback", readback.ms()});
  if (options.keep_buffers) {
    const State& s = *state_;
    add_gbuffer_buffers(download_gbuffer(s.gbuffer), frame.buffers);
    auto keep = [&](const char* stage, const char* name, const Texture& t) {
      if (s.ran(stage)) frame.buffers[name] = download_texture(t, 1);
    };
    keep("edge_detect", "edge_detect.contour_darkness", s.contour_darkness);
    keep("contour_light", "contour_light.lit_contour_darkness", s.lit_contour_darkness);
    keep("multi_contour", "multi_contour.contour_darkness", s.multi_contour_darkness);
    keep("interior_intensity", "interior_intensity.intensity", s.interior_intensity);
    keep("pencil_interior", "pencil_interior.interior_darkness", s.interior_darkness);
    frame.buffers["compose.color"] = frame.color;
  }
  Context::get().check_errors("reading back the frame");
  return frame;
}

}  // namespace plumbago::gpu
