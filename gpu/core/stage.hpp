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
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "common/core/frame_data.hpp"
#include "common/core/handle.hpp"
#include "common/core/preprocess.hpp"
#include "common/core/stage.hpp"
#include "common/scene/scene.hpp"
#include "gpu/core/limits.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/scene/gbuffer.hpp"

namespace plumbago::gpu {

// The data of one frame, by handle (common/core/handle.hpp). While a pass is made or runs
// (`running` holds its stages), every read of a Buffer, G-buffer or Slot is checked against
// its stages' descriptors: an undeclared read is a std::logic_error naming it.
class GpuFrame : public FrameData {
 public:
  GpuFrame(const Scene& scene, const Preprocessed& pre, std::vector<std::string> stages);

  const Scene& scene;
  Scene ordinary, sketchy;                // the objects each pipeline draws (common/sketchy/sketchy.hpp)
  const std::vector<std::string> stages;  // the frame stages that run
  bool dump = false;                      // a dump writes every output, the skipped ones too, in the whole window
  // The window lines (common/strokes/id_image.hpp) hold the paths the GPU made as well, read
  // back (Renderer::render: its counts; a dump always); else only those the CPU made.
  bool whole_lines = false;
  // The path frame the renderer drew last (none before its first), and whether every frame
  // follows the one drawn before it (Renderer::follow_every_frame).
  std::optional<int> last_drawn;
  bool every_frame_follows = false;

  // Whether what the last frame left carries into this one (on the reference: Carry::before):
  // it is the next frame of the camera path, or every frame follows.
  bool follows_last() const { return last_drawn && (every_frame_follows || *last_drawn + 1 == scene.frame); }
  // Whether a later frame may follow this one: the scene is a camera path, or every frame follows.
  bool may_be_followed() const { return every_frame_follows || scene.animation.has_value(); }

  template <class P>
  P params() const {
    return scene.params.get<P>();
  }
  StageConfig config() const { return {scene.params, scene.effects}; }
  // Whether `stage` runs in this frame; throws std::logic_error for a name no stage has.
  bool ran(const std::string& stage) const;
  // filter_rect(ordinary, radius) (common/scene/scene.hpp), its vertices projected once a
  // camera.
  PixelRect filter_rect(int radius) const;
  // `scene`'s view changed (common/scene/animation.hpp take_view): both pipelines' objects
  // take it.
  void camera_moved();

  // An output's render target, made on first use at the window's size in the declared
  // format; an output drawn over another (Output::draws_over) is that one's target where
  // its stage runs.
  Texture& put(plumbago::Buffer buffer);
  void put(plumbago::Buffer buffer, Texture texture);  // parity: an input made elsewhere
  // An output some pass wrote (or parity uploaded); throws std::logic_error naming it.
  const Texture& get(plumbago::Buffer buffer) const;
  const Texture* get(Maybe<plumbago::Buffer> buffer) const;  // null where not written

  void put(GBufferSlot gbuffer, const GBufferTargets& targets);
  const GBufferTargets& get(GBufferSlot gbuffer) const;

  template <class T>
  void put(Shared<T> shared, const T& object) {
    shared_[shared.name] = &object;
  }
  // None this frame (a pass that made one before and makes none now).
  template <class T>
  void withhold(Shared<T> shared) {
    shared_[shared.name] = static_cast<const T*>(nullptr);
  }
  template <class T>
  const T* get(Maybe<Shared<T>> shared) const {
    auto it = shared_.find(shared.handle.name);
    return it == shared_.end() ? nullptr : std::any_cast<const T*>(it->second);
  }
  template <class T>
  const T& get(Shared<T> shared) const {
    if (const T* object = get(maybe(shared))) return *object;
    throw std::logic_error(std::string("GPU frame: no pass made '") + shared.name + "'");
  }

  using FrameData::get;  // CPU data by Slot, made anew each frame
  using FrameData::put;

  // The dumps' and the frame color's access by a descriptor's name (not for stages).
  Texture& texture_named(const std::string& name);

  // What the frame's passes sample of a G-buffer ("gbuffer", "sketchy_gbuffer"): the targets
  // follow from the channels their stages declare as inputs (make_checked adds them); a pass
  // says where it reads them when it is made. The G-buffer writes only that (a dump: everything).
  void read_gbuffer(const std::string& stage, const GBufferChannels& channels);
  void read_region(GBufferSlot gbuffer, PixelRect region);
  // The region within `radius` pixels of the ordinary objects (filter_rect), for every camera.
  void read_near_objects(GBufferSlot gbuffer, int radius);
  GBufferChannels gbuffer_channels(const std::string& stage) const;

 private:
  mutable std::optional<WindowBounds> ordinary_bounds_;  // filter_rect's, made on first use
  std::map<std::string, Texture> textures_;
  std::map<std::string, std::any> shared_;
  std::map<std::string, GBufferChannels> gbuffer_reads_;
  std::map<std::string, int> gbuffer_radii_;  // read_near_objects: the largest radius a G-buffer
};

class GpuPass {
 public:
  virtual ~GpuPass() = default;
  virtual void run(GpuFrame& f) = 0;
  // Downloads what it wrote of `stages`' outputs (a dump): by default each written
  // output's texture.
  virtual void dump(GpuFrame& f, const std::vector<std::string>& stages, std::map<std::string, Image>& out);
  // After the frame's camera moved (GpuFrame::camera_moved), and with it the lights where
  // `lights_moved`: what the pass made once of them is made again. By default nothing.
  virtual void moved(GpuFrame&, bool /*lights_moved*/) {}
};

struct GpuPassDef {
  std::vector<std::string> stages;   // the stages it computes, in registry order
  std::vector<std::string> skipped;  // their outputs a frame does not write (a dump does)
  std::unique_ptr<GpuPass> (*make)(GpuFrame&) = nullptr;
  Probe probe = Probe::Fullscreen;  // the cheapest pass of its kind (gpu/core/limits.hpp), read against
  std::string name() const;         // "a+b"
};

template <class Pass>
std::unique_ptr<GpuPass> make_pass(GpuFrame& f) {
  return std::make_unique<Pass>(f);
}

// The probe a pass's time is read against, by the name a frame's timings give it
// (GpuPassDef::name(); "readback": Readback); Fullscreen for a name no pass has.
Probe probe_of(const std::string& pass);

// Makes and runs a pass with its reads checked against its stages' descriptors.
std::unique_ptr<GpuPass> make_checked(const GpuPassDef& def, GpuFrame& f);
void run_checked(const GpuPassDef& def, GpuPass& pass, GpuFrame& f);

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
// A table output of `records` records (common/util/image.hpp table_image): made at its size in
// the declared format the first time, then kept by the frame across frames. Throws
// std::runtime_error naming the table and GL's limit where its rows exceed the largest texture.
const Texture& table_target(GpuFrame& f, size_t records, plumbago::Buffer table);
// The prelude of a shader that includes util/common_table.glsl (common/util/image.hpp table_image).
inline std::string table_prelude() { return "#define TABLE_ROW " + std::to_string(kTableRow) + "\n"; }

}  // namespace plumbago::gpu

#define PLUMBAGO_GPU_PASS(id, ...) \
  [[maybe_unused]] static const bool registered_gpu_##id = ::plumbago::gpu::register_pass(__VA_ARGS__)
