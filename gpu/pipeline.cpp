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
#include "gpu/sketchy_composite.hpp"
#include "gpu/sketchy_enlarged.hpp"
#include "gpu/sketchy_maps.hpp"
#include "gpu/timer.hpp"

namespace plumbago::gpu {

namespace {

// Stages that one GPU pass computes together (one shader), so that a frame reads their
// inputs once and keeps no target between them: "a+b" replaces a followed by b. A dump
// has the shader write each stage's output (gpu/edge_detect.hpp, gpu/compose.hpp).
std::vector<std::string> fused(const std::vector<std::string>& stages) {
  static const std::vector<std::pair<std::string, std::string>> pairs = {{"edge_detect", "contour_light"},
                                                                         {"interior_intensity", "pencil_interior"},
                                                                         {"multi_contour", "compose"}};
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

// The sketchy objects' passes and buffers (SPEC 3), made only for a scene that has them.
struct SketchyState {
  Scene sketchy;
  GBufferPass gbuffer_pass{sketchy};
  GBufferTargets gbuffer;
  std::unique_ptr<SketchyEnlargedPass> enlarged_pass;  // object style only
  Texture noise_coordinates, edge_map, shade_map, sprite_depth;
  SketchyNoiseTextures noise;
  SketchyMapsPass maps_pass{object_colors(sketchy)};
  SketchyCompositePass composite_pass;

  SketchyState(const Scene& scene, const SketchyNoise& n, bool object_style)
      : sketchy(sketchy_objects(scene)),
        gbuffer(make_gbuffer_targets(scene.width, scene.height, scene.params.get<GBufferParams>().normal_format)),
        enlarged_pass(object_style ? std::make_unique<SketchyEnlargedPass>(enlarged_scene(sketchy)) : nullptr),
        noise_coordinates(make_texture(scene.width, scene.height, GL_RGBA32F)),
        edge_map(make_texture(scene.width, scene.height, GL_RG32F)),
        shade_map(make_texture(scene.width, scene.height, GL_RGBA8)),
        sprite_depth(make_texture(scene.width, scene.height, GL_R32F)),
        noise(upload_sketchy_noise(n)) {
    set_sampling(edge_map, GL_LINEAR, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);  // darkness is read filtered
  }

  // The sketchy G-buffer feeds only the edge map: normals of the edge mode, depth, ids.
  static GBufferChannels channels(const Scene& scene) {
    bool face = scene.params.get<EdgeDetectParams>().normals == EdgeNormals::Face;
    return {!face, face, false, false, false, false};
  }
};

}  // namespace

struct Renderer::State {
  const Scene& scene;
  Scene ordinary = ordinary_objects(scene);
  std::vector<std::string> passes = passes_for(scene.effects, scene.params);
  std::vector<std::string> stages = frame_stages(passes);
  std::vector<std::string> gpu_passes = fused(stages);
  Preprocessed pre = preprocess(ordinary, passes);
  ContourInputs contour_inputs = pre.offset_grids.empty() ? ContourInputs{}
      : make_contour_inputs(scene.params.get<ContourParams>(), pre.offset_grids, pre.contour_texture, pre.texture_shifts,
                            scene.width, scene.height);
  Texture pencil_stack = pre.pencil_stack.empty() ? make_texture(1, 1, GL_R32F) : upload_texture_3d(pre.pencil_stack, GL_R32F);
  Texture paper_normal = pre.paper.normal.empty() ? make_texture(1, 1, GL_RGBA32F) : upload_texture(pre.paper.normal, GL_RGBA32F);
  Texture paper_color = pre.paper.color.empty() ? make_texture(1, 1, GL_RGBA32F) : upload_texture(pre.paper.color, GL_RGBA32F);
  GBufferPass gbuffer_pass{ordinary, pre.curvature};
  EdgeDetectPass edge_pass;
  MultiContourPass multi_contour_pass;
  PencilInteriorPass pencil_interior_pass;
  ComposePass compose_pass;
  GBufferTargets gbuffer = make_gbuffer_targets(scene.width, scene.height,
                                                scene.params.get<GBufferParams>().normal_format);
  Texture lit_contour_darkness = make_texture(scene.width, scene.height, GL_R32F);
  Texture contour_block_marks = make_contour_block_marks(scene.width, scene.height);  // by the edge pass
  Texture interior_darkness = make_texture(scene.width, scene.height, GL_R32F);
  Texture color = make_texture(scene.width, scene.height, GL_RGBA8);
  PassTimer timer;
  GBufferChannels gbuffer_channels = channels_read_by(stages, scene);  // all of them for a dump
  bool dump = false;  // a dump composes the whole window: tests compare it with a frame
  // What only a dump writes (`--dump-stages`, `compare`): the unlit d, the D_c drawn in
  // the composition, I'. Made by the first dump; a frame writes none of them.
  struct DumpTargets {
    Texture contour_darkness, multi_contour_darkness, interior_intensity;
  };
  std::unique_ptr<DumpTargets> dumped;
  std::unique_ptr<SketchyState> sketchy = !ran("sketchy_composite") ? nullptr
      : std::make_unique<SketchyState>(scene, pre.sketchy_noise, ran("sketchy_enlarged"));
  GBufferChannels sketchy_channels = SketchyState::channels(scene);

  explicit State(const Scene& s) : scene(s) {}

  bool ran(const char* stage) const { return std::find(stages.begin(), stages.end(), stage) != stages.end(); }

  ComposeInputs compose_inputs() const {
    return {interior_darkness, ran("pencil_interior"), paper_color, !pre.paper.color.empty()};
  }

  // Where D_c or D_i can differ from 0: around the contours' reach, or the objects.
  PixelRect compose_rect() const {
    if (dump) return {0, 0, scene.width, scene.height};
    return ran("multi_contour") ? contour_rect(ordinary, pre.offset_grids) : filter_rect(ordinary, 0);
  }

  void run(const std::string& pass) {
    if (pass == "gbuffer") {
      gbuffer_pass.render(scene, gbuffer, gbuffer_channels);
    } else if (pass == "edge_detect+contour_light") {
      edge_pass.run(gbuffer, scene.params.get<EdgeDetectParams>(), view_space_lights(scene),
                    scene.params.get<ContourLightParams>(),
                    {lit_contour_darkness, dump ? &dumped->contour_darkness : nullptr,
                     ran("multi_contour") ? &contour_block_marks : nullptr},
                    filter_rect(ordinary, 1));
    } else if (pass == "interior_intensity+pencil_interior") {
      pencil_interior_pass.run(gbuffer, gbuffer_pass.triangle_angles(), view_space_lights(scene), pencil_stack, paper_normal,
                               interior_options(scene.effects), scene.params.get<InteriorParams>(),
                               scene.params.get<PaperParams>().mu_p, interior_darkness, dump ? &dumped->interior_intensity : nullptr,
                               filter_rect(ordinary, 0));
    } else if (pass == "multi_contour+compose") {
      // The contours are drawn in the composition pass; a dump also keeps their D_c.
      ContourSources contours = multi_contour_pass.prepare(lit_contour_darkness, contour_inputs,
                                                           scene.params.get<ContourParams>(), &contour_block_marks);
      compose_pass.run(contours, compose_inputs(), scene.params.get<ComposeParams>(), color, compose_rect(),
                       dump ? &dumped->multi_contour_darkness : nullptr);
    } else if (pass == "compose") {  // no contours (they would have been fused in): D_c is not read
      compose_pass.run(lit_contour_darkness, false, compose_inputs(), scene.params.get<ComposeParams>(), color,
                       compose_rect());
    } else if (pass == "sketchy_gbuffer") {
      sketchy->gbuffer_pass.render(scene, sketchy->gbuffer, sketchy_channels);
    } else if (pass == "sketchy_enlarged") {
      sketchy->enlarged_pass->render(scene.camera, sketchy->noise_coordinates);
    } else if (pass == "sketchy_maps") {
      sketchy->maps_pass.run(sketchy->gbuffer, scene.params.get<EdgeDetectParams>(), sketchy->edge_map, sketchy->shade_map,
                             filter_rect(sketchy->sketchy, 1));
    } else if (pass == "sketchy_composite") {
      SketchyState& s = *sketchy;
      s.composite_pass.run({s.edge_map, s.shade_map, s.gbuffer, s.noise, s.noise_coordinates},
                           scene.params.get<SketchyParams>(), color, ran("gbuffer") ? &gbuffer_pass.depth_buffer() : nullptr,
                           s.sprite_depth, composite_rect(s.sketchy, scene.width, scene.height));
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

namespace {

void add_sketchy_buffers(const SketchyState& s, bool enlarged, std::map<std::string, Image>& out) {
  add_gbuffer_buffers(download_gbuffer(s.gbuffer), out, "sketchy_gbuffer");
  if (enlarged) out["sketchy_enlarged.noise_coordinates"] = download_texture(s.noise_coordinates, 4);
  out["sketchy_maps.edge"] = download_texture(s.edge_map, 2);
  out["sketchy_maps.shade"] = download_texture(s.shade_map, 4);
  out["sketchy_composite.depth"] = download_texture(s.sprite_depth, 1);
}

}  // namespace

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
  state_->dump = options.keep_buffers;
  if (options.keep_buffers && !state_->dumped) {
    const int w = state_->scene.width, h = state_->scene.height;
    state_->dumped = std::make_unique<State::DumpTargets>(State::DumpTargets{
        make_texture(w, h, GL_R32F), make_texture(w, h, GL_R32F), make_texture(w, h, GL_R32F)});
  }
  state_->sketchy_channels = options.keep_buffers ? GBufferChannels{} : SketchyState::channels(state_->scene);
  state_->run_frame();
  frame.ran = state_->pre.ran;  // once per Renderer, listed with every frame it renders
  for (const PassTime& t : state_->timer.results()) frame.ran.push_back(t);
  Stopwatch readback;
  frame.color = download_texture(state_->color, 3);
  frame.ran.push_back({"readback", readback.ms()});
  if (options.keep_buffers) {
    const State& s = *state_;
    if (s.ran("gbuffer")) add_gbuffer_buffers(download_gbuffer(s.gbuffer), frame.buffers);
    auto keep = [&](const char* stage, const char* name, const Texture& t) {
      if (s.ran(stage)) frame.buffers[name] = download_texture(t, 1);
    };
    keep("edge_detect", "edge_detect.contour_darkness", s.dumped->contour_darkness);
    keep("contour_light", "contour_light.lit_contour_darkness", s.lit_contour_darkness);
    keep("multi_contour", "multi_contour.contour_darkness", s.dumped->multi_contour_darkness);
    keep("interior_intensity", "interior_intensity.intensity", s.dumped->interior_intensity);
    keep("pencil_interior", "pencil_interior.interior_darkness", s.interior_darkness);
    if (s.sketchy) add_sketchy_buffers(*s.sketchy, s.ran("sketchy_enlarged"), frame.buffers);
    frame.buffers[s.sketchy ? "sketchy_composite.color" : "compose.color"] = frame.color;
  }
  Context::get().check_errors("reading back the frame");
  return frame;
}

}  // namespace plumbago::gpu
