#include "parity/parity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <map>
#include <set>
#include <stdexcept>

#include "common/core/passes.hpp"
#include "common/scene/gbuffer.hpp"
#include "common/util/memory_budget.hpp"
#include "common/util/progress.hpp"
#include "gpu/core/pipeline.hpp"
#include "gpu/core/stage.hpp"
#include "gpu/gl/context.hpp"
#include "reference/core/pipeline.hpp"

namespace plumbago {

namespace {

// End to end: at most this share of pixels may differ by more than 2/255 (measured on
// the built-in scenes and the shared models: see tests/core/end_to_end_test.cpp).
constexpr double kEndToEndShare = 0.05;

bool contains(const std::vector<std::string>& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

bool across_discontinuity(const GBuffer& g, int x, int y, int nx, int ny) {
  if (g.ids.at(x, y, 0) != g.ids.at(nx, ny, 0)) return true;
  float d = g.depth.at(x, y), dn = g.depth.at(nx, ny);
  return std::abs(d - dn) > kDepthJump * std::min(d, dn);
}

bool near_discontinuity(const GBuffer& g, int x, int y) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      int nx = std::clamp(x + dx, 0, g.depth.width - 1), ny = std::clamp(y + dy, 0, g.depth.height - 1);
      if (across_discontinuity(g, x, y, nx, ny)) return true;
    }
  return false;
}

Image same_triangle(const GBuffer& a, const GBuffer& b, const Image& interior) {
  Image m = interior;
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x)
      if (a.ids.at(x, y, 1) != b.ids.at(x, y, 1)) m.at(x, y) = 0;
  return m;
}

// Pixels covered (alpha > 0) in both images with their 3x3 neighborhood: coverage itself
// is a raster-vs-ray question (the G-buffer's band), not the stage's.
Image covered_interior(const Image& a, const Image& b) {
  Image m(a.width, a.height, 1);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      bool inside = true;
      for (int dy = -1; dy <= 1 && inside; ++dy)
        for (int dx = -1; dx <= 1 && inside; ++dx) {
          int nx = std::clamp(x + dx, 0, a.width - 1), ny = std::clamp(y + dy, 0, a.height - 1);
          inside = a.at(nx, ny, 3) > 0 && b.at(nx, ny, 3) > 0;
        }
      m.at(x, y) = inside ? 1.0f : 0.0f;
    }
  return m;
}

double share(const Image& mask) {
  double n = 0;
  for (float v : mask.data) n += v > 0.5f;
  return n / double(mask.pixels());
}

// Angles compared as (cos, sin) pairs, so that -pi and pi agree.
Image angle_vectors(const Image& theta) {
  Image v(theta.width, theta.height, theta.channels * 2);
  for (size_t i = 0; i < theta.data.size(); ++i) {
    v.data[2 * i] = std::cos(theta.data[i]);
    v.data[2 * i + 1] = std::sin(theta.data[i]);
  }
  return v;
}

// `gpu` with each difference from `ref` shrunk by the pixel's bound (at most to 0): what is
// left over the declared tolerance is what the bound does not explain.
Image within_bound(const Image& ref, const Image& gpu, const Image& bound) {
  Image out = gpu;
  for (size_t i = 0; i < out.data.size(); ++i) {
    float b = bound.data[i / size_t(out.channels)], d = gpu.data[i] - ref.data[i];
    out.data[i] = ref.data[i] + std::copysign(std::max(0.0f, std::abs(d) - b), d);
  }
  return out;
}

// The masks of a rasterizing stage's outputs: where both G-buffers see the same surface.
struct RasterMasks {
  Image interior, same_triangle;
  std::string band;  // the shares, for the notes
};

RasterMasks raster_masks(const GBuffer& ref, const GBuffer& ras) {
  RasterMasks m{interior_mask(ref, ras), {}, {}};
  m.same_triangle = same_triangle(ref, ras, m.interior);
  double covered = 0;
  for (size_t i = 0; i < ref.ids.pixels(); ++i) covered += ref.ids.data[i * 2] || ras.ids.data[i * 2];
  char band[160];
  std::snprintf(band, sizeof band, "; interior %.1f%% of the image; band excluded %.2f%% of the image",
                100 * share(m.interior), 100 * (covered / double(ref.ids.pixels()) - share(m.interior)));
  m.band = band;
  return m;
}

// The scene with the effect that makes `stage` run added (itself when it runs); false when
// no effect runs it there. An effect that goes with a style (EffectDef::styled) is never
// added: the scene has it exactly when it has objects of that style.
bool scene_running(const Scene& scene, const std::string& stage, Scene& out) {
  auto runs = [&](const std::vector<std::string>& effects) {
    return contains(passes_for(effects, scene.params), stage);
  };
  out = scene;
  if (runs(scene.effects)) return true;
  for (const EffectDef& e : effect_table()) {
    out.effects = scene.effects;
    out.effects.push_back(e.name);
    if (!e.styled && !contains(scene.effects, e.name) && runs(out.effects)) return true;
  }
  return false;
}

// The inputs of `pass`'s stages made outside it and fed by parity (preprocessing is shared
// as it is: the GPU pass uploads it itself).
std::vector<std::string> fed_inputs(const gpu::GpuPassDef& pass, const StageConfig& config) {
  std::vector<std::string> fed;
  for (const std::string& name : pass.stages)
    for (const Input& in : find_stage(name).inputs) {
      const StageDesc& from = stage_of(in.buffer());
      bool read = !in.used || in.used(config);
      bool image = find_output(in.buffer()).texel != Texel::Host;  // CPU data is handed over as it is
      if (read && image && in.fed_in_parity && from.kind == StageKind::Frame && !contains(pass.stages, from.name) &&
          !contains(fed, in.buffer()))
        fed.push_back(in.buffer());
    }
  return fed;
}

// Both backends' outputs of one GPU pass fed the same inputs: the reference's half when
// made (CPU only), the GPU's and the comparison in compare().
class PassParity {
 public:
  PassParity(const Scene& scene, const reference::ReferenceFrame& ref, const gpu::GpuPassDef& pass)
      : pass_(pass), rf_(scene, ref.pre, pass.stages), gf_(scene, rf_.pre, pass.stages) {
    gf_.dump = true;                 // every output, the skipped ones too, in the whole window
    rf_.data = gf_.data = ref.data;  // CPU data (the window lines, the visible runs) as it is
    for (const std::string& buffer : fed_inputs(pass, rf_.config())) feed(ref, buffer);
    for (const std::string& stage : pass_.stages) reference::run_stage(rf_, stage);
    ref_out_ = reference::dump(rf_);
  }

  std::vector<StageParity> compare() {
    for (const auto& [buffer, image] : fed_images_)
      gf_.put(Buffer{buffer.c_str()}, gpu::upload_texture(image, gpu::texture_format(find_output(buffer))));
    for (const std::string& producer : fed_gbuffers_) {
      const GBuffer& g = rf_.gbuffers.at(producer);
      gf_.put(GBufferSlot{producer.c_str()}, uploaded_.emplace_back(gpu::upload_gbuffer(g)));
      if (producer == kGBuffer.name) gf_.put(gpu::kTriangleAngles, angles_.emplace_back(gpu::triangle_angles_from(g)));
    }
    std::unique_ptr<gpu::GpuPass> gpu_pass = gpu::make_checked(pass_, gf_);
    gpu::run_checked(pass_, *gpu_pass, gf_);
    std::map<std::string, Image> gpu_out;
    gpu_pass->dump(gf_, pass_.stages, gpu_out);
    gpu::Context::get().check_errors(pass_.name() + " parity");
    std::vector<StageParity> results;
    for (const std::string& name : dumped_buffers(pass_.stages, rf_.config()))
      if (find_output(name).compared) results.push_back(compare_output(name, ref_out_.at(name), gpu_out.at(name)));
    return results;
  }

 private:
  // The reference's buffer, put in the reference frame (and kept to upload to the GPU).
  void feed(const reference::ReferenceFrame& ref, const std::string& buffer) {
    const std::string producer = stage_of(buffer).name;
    auto g = ref.gbuffers.find(producer);
    if (g == ref.gbuffers.end()) {
      rf_.images[buffer] = ref.images.at(buffer);
      fed_images_[buffer] = ref.images.at(buffer);
    } else if (!rf_.gbuffers.count(producer)) {
      rf_.gbuffers[producer] = g->second;
      fed_gbuffers_.push_back(producer);
    }
  }

  // A rasterizing stage's G-buffers, where the pass made one.
  const RasterMasks& masks(const std::string& stage) {
    auto it = masks_.find(stage);
    if (it == masks_.end())
      it = masks_
               .emplace(stage, raster_masks(rf_.gbuffers.at(stage),
                                            gpu::download_gbuffer(gf_.get(GBufferSlot{stage.c_str()}))))
               .first;
    return it->second;
  }

  StageParity compare_output(const std::string& name, Image ref, Image ras) {
    const Output& o = find_output(name);
    std::string note = o.tolerance_why;
    if (pass_.stages.size() > 1) note += "; computed in GPU pass " + pass_.name() + " (a frame's way)";
    const Image* mask = nullptr;
    Image covered;
    if (o.mask == ParityMask::Interior || o.mask == ParityMask::SameTriangle) {
      const RasterMasks& m = masks(stage_of(name).name);
      mask = o.mask == ParityMask::Interior ? &m.interior : &m.same_triangle;
      if (o.mask == ParityMask::Interior) note += m.band;
    } else if (o.mask == ParityMask::Covered) {
      covered = covered_interior(ref, ras);
      mask = &covered;
    }
    std::string shown = pass_.stages.size() > 1 ? name + " in " + pass_.name() : name;
    if (o.value == ParityValue::Angles) {  // compared as (cos, sin); kept as angles, viewable
      StageParity r = compared(shown, angle_vectors(ref), angle_vectors(ras), o.tolerance, mask, note);
      r.reference = std::move(ref), r.gpu = std::move(ras);
      return r;
    }
    reference::BoundFn bound = reference::find_bound(name);
    if (!bound) return compared(shown, std::move(ref), std::move(ras), o.tolerance, mask, note);
    Image b = bound(rf_);
    ImageDiff raw = compare_images(ref, ras, o.tolerance, mask);
    size_t bounded = size_t(std::count_if(b.data.begin(), b.data.end(), [&](float v) { return v > o.tolerance; }));
    char text[200];
    std::snprintf(text, sizeof text,
                  "; a derived per-pixel bound over the tolerance at %zu pixels (max abs without it %.3g)", bounded,
                  raw.max_abs);
    StageParity r = compared(shown, ref, within_bound(ref, ras, b), o.tolerance, mask, note + text);
    r.gpu = std::move(ras);  // what the GPU wrote; the diff is what the bound leaves
    r.bounded = bounded;
    return r;
  }

  const gpu::GpuPassDef& pass_;
  reference::ReferenceFrame rf_;
  gpu::GpuFrame gf_;
  std::map<std::string, Image> fed_images_, ref_out_;
  std::vector<std::string> fed_gbuffers_;
  std::deque<gpu::GBufferTargets> uploaded_;
  std::deque<gpu::TriangleAngles> angles_;
  std::map<std::string, RasterMasks> masks_;
};

// The GPU passes that compute `stage`: alone first, then fused, by name.
std::vector<const gpu::GpuPassDef*> passes_computing(const std::string& stage) {
  std::vector<const gpu::GpuPassDef*> passes;
  for (const gpu::GpuPassDef& p : gpu::registered_passes())
    if (contains(p.stages, stage)) passes.push_back(&p);
  std::sort(passes.begin(), passes.end(), [](const gpu::GpuPassDef* a, const gpu::GpuPassDef* b) {
    return std::pair(a->stages.size(), a->name()) < std::pair(b->stages.size(), b->name());
  });
  return passes;
}

// Whole frames (docs/conventions.md "end to end"): each backend from its own G-buffer and every pass
// of the scene's effects. Pixels differ where the rasterizer and the tracer disagree on
// coverage (the band along silhouettes) and wherever that moves a contour copy or a
// stroke; the share of pixels within 2/255 is what is reported and bounded per scene.
StageParity end_to_end_parity(const Frame& ref, const Scene& scene) {
  Frame gpu_frame = gpu::Renderer(scene).render();
  StageParity s = compared("end_to_end", ref.color, gpu_frame.color, 2.0 / 255.0, nullptr,
                           "whole frames, each backend from its own G-buffer");
  s.pass = s.diff.over_tolerance <= kEndToEndShare;
  return s;
}

}  // namespace

// The reference frames of the scenes parity runs, made once per set of effects.
class ParityRun::References {
 public:
  const reference::ReferenceFrame& of(const Scene& scene) {
    auto it = frames_.find(scene.effects);
    if (it == frames_.end()) {
      scenes_.push_back(scene);
      std::vector<PassTime> ran;
      it = frames_.emplace(scene.effects, reference::run_stages(scenes_.back(), ran)).first;
    }
    return it->second;
  }

 private:
  std::deque<Scene> scenes_;  // the frames refer to them
  std::map<std::vector<std::string>, reference::ReferenceFrame> frames_;
};

void check_stage_registry() {
  stage_table();
  param_specs();
  reference::check_implementations();
  gpu::check_implementations();
}

StageParity compared(std::string name, Image ref, Image gpu, double tol, const Image* mask, std::string note) {
  StageParity s{std::move(name), compare_images(ref, gpu, tol, mask), false, std::move(ref), std::move(gpu),
                std::move(note)};
  s.pass = s.diff.over_tolerance == 0;
  return s;
}

Image interior_mask(const GBuffer& a, const GBuffer& b) {
  Image m(a.depth.width, a.depth.height, 1);
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) {
      bool hit = !a.background(x, y) && a.ids.at(x, y, 0) == b.ids.at(x, y, 0);
      m.at(x, y) = hit && !near_discontinuity(a, x, y) && !near_discontinuity(b, x, y) ? 1.0f : 0.0f;
    }
  return m;
}

std::vector<std::string> parity_stages() {
  std::vector<std::string> names = frame_stages([] {
    std::vector<std::string> all;
    for (const StageDesc& s : stage_table()) all.push_back(s.name);
    return all;
  }());
  names.push_back("end_to_end");
  return names;
}

namespace {

// What the run would hold at once, against the memory budget before it starts: the
// reference frames it keeps (one per set of effects its steps run), a step's two halves
// (its pass's reference frame and the GPU's), and both backends' outputs of every stage it
// compares; each at most a whole frame (frame_bytes_per_pixel).
void check_parity_memory(const Scene& scene, size_t kept_frames) {
  const double frames = double(kept_frames) + 4, pixels = double(scene.width) * scene.height;
  char what[300];
  std::snprintf(what, sizeof what,
                "%s: compare at %dx%d (%zu reference frames kept, a step's two halves and both backends' results: %g "
                "frames of up to %g bytes a pixel)",
                scene.source.c_str(), scene.width, scene.height, kept_frames, frames, frame_bytes_per_pixel());
  check_memory_budget(what, frames * pixels * frame_bytes_per_pixel());
}

}  // namespace

// One step: a GPU pass on the scene that runs it, or (no pass) the whole frames.
struct ParityRun::Step {
  Scene running;
  const gpu::GpuPassDef* pass = nullptr;
  std::unique_ptr<PassParity> parity;
  Frame reference;  // end to end
};

ParityRun::ParityRun(const Scene& scene, const std::vector<std::string>& stages) {
  const std::vector<std::string> known = parity_stages();
  for (const auto& s : stages)
    if (!contains(known, s)) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      throw std::invalid_argument("unknown stage '" + s + "' (known: " + list + ")");
    }
  check_stage_registry();
  std::vector<std::string> checked;  // GPU passes, each once
  for (const std::string& stage : known) {
    if (!stages.empty() && !contains(stages, stage)) continue;
    Scene running;
    if (stage == "end_to_end") steps_.push_back(std::make_unique<Step>(Step{scene, nullptr, {}, {}}));
    if (stage == "end_to_end" || !scene_running(scene, stage, running)) continue;
    std::vector<std::string> runs = frame_stages(passes_for(running.effects, running.params));
    for (const gpu::GpuPassDef* pass : passes_computing(stage)) {
      bool all_run = std::all_of(pass->stages.begin(), pass->stages.end(),
                                 [&](const std::string& s) { return contains(runs, s); });
      if (!all_run || contains(checked, pass->name())) continue;
      checked.push_back(pass->name());
      steps_.push_back(std::make_unique<Step>(Step{running, pass, {}, {}}));
    }
  }
  std::set<std::vector<std::string>> kept;
  for (const auto& step : steps_)
    if (step->pass) kept.insert(step->running.effects);
  check_parity_memory(scene, kept.size());
}

ParityRun::~ParityRun() = default;

void ParityRun::reference(size_t i) {
  Step& step = *steps_.at(i);
  if (!step.pass) {
    step.reference = reference::render(step.running);
    return;
  }
  if (!references_) references_ = std::make_unique<References>();
  const reference::ReferenceFrame& ref = references_->of(step.running);
  step.parity = std::make_unique<PassParity>(ref.scene, ref, *step.pass);
}

std::vector<StageParity> ParityRun::gpu(size_t i) {
  Step& step = *steps_.at(i);
  gpu::Context::get();
  std::vector<StageParity> out =
      step.pass ? step.parity->compare() : std::vector<StageParity>{end_to_end_parity(step.reference, step.running)};
  steps_[i].reset();
  return out;
}

nlohmann::json parity_report(const std::vector<StageParity>& results) {
  bool all_pass = std::all_of(results.begin(), results.end(), [](const StageParity& s) { return s.pass; });
  nlohmann::json j{
      {"pass", all_pass}, {"renderer", gpu::Context::get().renderer()}, {"stages", nlohmann::json::array()}};
  for (const auto& s : results)
    j["stages"].push_back({{"name", s.name},
                           {"pass", s.pass},
                           {"max_abs", s.diff.max_abs},
                           {"rmse", s.diff.rmse},
                           {"over_tolerance", s.diff.over_tolerance},
                           {"tolerance", s.diff.tolerance},
                           {"compared_pixels", s.diff.compared},
                           {"bounded_pixels", s.bounded},
                           {"note", s.note}});
  return j;
}

std::vector<StageParity> run_parity(const Scene& scene, const std::vector<std::string>& stages) {
  gpu::Context::get();
  ParityRun run(scene, stages);
  Progress progress(scene.source + ": compare, steps", run.size(), true);
  std::vector<StageParity> out;
  for (size_t i = 0; i < run.size(); ++i, progress.advance(1)) {
    run.reference(i);
    for (auto& s : run.gpu(i)) out.push_back(std::move(s));
  }
  return out;
}

}  // namespace plumbago
