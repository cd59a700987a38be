// Stages on the GPU. A GPU pass computes one stage, or several in one shader (a fused
// pass: the frame reads their inputs once and keeps no target between them), and
// registers itself next to its code (gpu/<stem>.cpp):
//
//   PLUMBAGO_GPU_PASS(edge_detect, {{"edge_detect", "contour_light"},   // computes both
//                                   {"edge_detect.contour_darkness"},  // a frame skips writing d
//                                   make_pass<EdgePass>});
//
// A frame runs each stage through the pass that computes the most of the frame's stages
// (a fused pass runs where its last stage would); its passes read and write buffers by
// their declared names (common/core/stage.hpp) through the GpuFrame. A frame stage that no
// pass computes is an error when a renderer starts.
#pragma once

#include <any>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "common/core/host_data.hpp"
#include "common/core/preprocess.hpp"
#include "common/scene/scene.hpp"
#include "common/core/stage.hpp"
#include "gpu/scene/gbuffer.hpp"
#include "gpu/gl/gl_objects.hpp"

namespace plumbago::gpu {

class GpuFrame {
 public:
  GpuFrame(const Scene& scene, const Preprocessed& pre, std::vector<std::string> stages);

  const Scene& scene;
  Scene ordinary, sketchy;  // the objects each pipeline draws (common/sketchy/sketchy.hpp)
  const Preprocessed& pre;
  const std::vector<std::string> stages;  // the frame stages that run
  bool dump = false;  // a dump writes every output, the skipped ones too, in the whole window
  HostData host;     // CPU data the stages share this frame (common/core/host_data.hpp)
  HostData kept;     // CPU data kept across the renderer's frames (what does not depend on the view)

  template <class P>
  P params() const {
    return scene.params.get<P>();
  }
  StageConfig config() const { return {scene.params, scene.effects}; }
  // Whether `stage` runs in this frame; throws std::logic_error for a name no stage has.
  bool ran(const std::string& stage) const;

  // A declared output's texture, made on first use at the window's size in the declared
  // format; an output drawn over another (Output::draws_over) is that one's texture where
  // its stage runs.
  Texture& output(const std::string& name);
  // An output that a frame skips writing: its texture in a dump, else null.
  Texture* dumped_output(const std::string& name) { return dump ? &output(name) : nullptr; }
  // An output some pass wrote (or parity uploaded); throws std::logic_error naming it.
  const Texture& input(const std::string& name) const;
  bool has(const std::string& name) const { return textures_.count(name) != 0; }
  void set_output(const std::string& name, Texture texture) { textures_[name] = std::move(texture); }

  // What passes share besides textures (a G-buffer's targets, its depth buffer), by name.
  template <class T>
  void share(const std::string& name, T& object) {
    shared_[name] = const_cast<std::remove_const_t<T>*>(&object);  // a reader asks for const or not
  }
  template <class T>
  T* find_shared(const std::string& name) const {
    auto it = shared_.find(name);
    return it == shared_.end() ? nullptr : std::any_cast<std::remove_const_t<T>*>(it->second);
  }
  template <class T>
  T& shared(const std::string& name) const {
    if (T* object = find_shared<T>(name)) return *object;
    throw std::logic_error("GPU frame: no pass made '" + name + "'");
  }

  // What the frame's passes sample of a G-buffer ("gbuffer", "sketchy_gbuffer"): each
  // pass says so when it is made, and the G-buffer writes only that (a dump: everything).
  void read_gbuffer(const std::string& stage, const GBufferChannels& channels);
  GBufferChannels gbuffer_channels(const std::string& stage) const;

 private:
  std::map<std::string, Texture> textures_;
  std::map<std::string, std::any> shared_;
  std::map<std::string, GBufferChannels> gbuffer_reads_;
};

class GpuPass {
 public:
  virtual ~GpuPass() = default;
  virtual void run(GpuFrame& f) = 0;
  // Downloads what it wrote of `stages`' outputs (a dump): by default each written
  // output's texture.
  virtual void dump(GpuFrame& f, const std::vector<std::string>& stages, std::map<std::string, Image>& out);
};

struct GpuPassDef {
  std::vector<std::string> stages;   // the stages it computes, in registry order
  std::vector<std::string> skipped;  // their outputs a frame does not write (a dump does)
  std::unique_ptr<GpuPass> (*make)(GpuFrame&) = nullptr;
  std::string name() const;  // "a+b"
};

template <class Pass>
std::unique_ptr<GpuPass> make_pass(GpuFrame& f) {
  return std::make_unique<Pass>(f);
}

// Called by PLUMBAGO_GPU_PASS; throws std::logic_error for an unknown stage, a skipped
// output its stages do not declare, or a pass registered twice.
bool register_pass(GpuPassDef def);
const std::vector<GpuPassDef>& registered_passes();
// Throws std::logic_error naming every frame stage that no GPU pass computes.
void check_implementations();
// The passes that compute `stages` (registry order), in the order they run. Throws
// std::logic_error when a stage has no pass here, or another stage reads what a fused
// pass skips.
std::vector<const GpuPassDef*> plan_passes(const std::vector<std::string>& stages, const StageConfig& config);

// The GL texture format of a declared output.
GLenum texture_format(const Output& output);

}  // namespace plumbago::gpu

#define PLUMBAGO_GPU_PASS(id, ...) \
  [[maybe_unused]] static const bool registered_gpu_##id = ::plumbago::gpu::register_pass(__VA_ARGS__)
