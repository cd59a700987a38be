// Stages on the reference backend: each registers its implementation next to its code
// (reference/<subsystem>/<stem>.cpp), a plain function that reads its declared inputs from
// a ReferenceFrame through their handles (common/core/handle.hpp) and puts its outputs there:
//
//   PLUMBAGO_REFERENCE_STAGE(edge_detect, [](ReferenceFrame& f) {
//     f.put(kContourDarkness, contour_darkness(f.get(kGBuffer), f.params<EdgeDetectParams>()));
//   });
#pragma once

#include <map>
#include <string>
#include <vector>

#include "common/core/frame_data.hpp"
#include "common/core/handle.hpp"
#include "common/core/preprocess.hpp"
#include "common/core/stage.hpp"
#include "common/scene/gbuffer.hpp"
#include "common/scene/scene.hpp"

namespace plumbago::reference {

// The data of one frame, by handle. A stage that runs (run_stage) may read only what its
// descriptor declares: any other read is a std::logic_error naming it.
struct ReferenceFrame : FrameData {
  ReferenceFrame(const Scene& scene, Preprocessed pre, std::vector<std::string> stages);

  const Scene& scene;
  Scene ordinary, sketchy;          // the objects each pipeline draws (common/sketchy/sketchy.hpp)
  std::vector<std::string> stages;  // the frame stages that run

  template <class P>
  P params() const {
    return scene.params.get<P>();
  }
  StageConfig config() const { return {scene.params, scene.effects}; }

  // An input; std::logic_error naming it when no stage made it.
  const Image& get(Buffer buffer) const;
  const Image* get(Maybe<Buffer> buffer) const;  // null where not made
  void put(Buffer buffer, Image image);
  const GBuffer& get(GBufferSlot gbuffer) const;
  const GBuffer* get(Maybe<GBufferSlot> gbuffer) const;  // null where not made
  void put(GBufferSlot gbuffer, GBuffer value);
  using FrameData::get;  // CPU data by Slot
  using FrameData::put;

  std::map<std::string, Image> images;
  std::map<std::string, GBuffer> gbuffers;
};

// Runs `stage`'s implementation on `f`, its reads checked against its descriptor.
void run_stage(ReferenceFrame& f, const std::string& stage);

using StageFn = void (*)(ReferenceFrame&);

// Called by PLUMBAGO_REFERENCE_STAGE; throws std::logic_error for an unknown or twice
// registered stage.
bool register_stage(const char* stage, StageFn fn);
// Throws std::logic_error naming every frame stage that has no reference implementation.
void check_implementations();
StageFn implementation(const std::string& stage);

// A per-pixel bound for an output whose backends may differ by more than its declared
// tolerance at rare pixels the formula can name (a nearest-texel choice at a texel edge):
// parity allows the declared tolerance plus bound(x, y). Registered with
// PLUMBAGO_REFERENCE_BOUND next to the stage's code, computed from the frame's inputs.
using BoundFn = Image (*)(const ReferenceFrame&);
bool register_bound(const char* output, BoundFn fn);
BoundFn find_bound(const std::string& output);  // null when the output has none

// The buffers a dump of `frame` holds, by name (common/core/stage.hpp dumped_buffers).
std::map<std::string, Image> dump(const ReferenceFrame& frame);

}  // namespace plumbago::reference

#define PLUMBAGO_REFERENCE_STAGE(stem, ...)                        \
  [[maybe_unused]] static const bool registered_reference_##stem = \
      ::plumbago::reference::register_stage(#stem, __VA_ARGS__)
#define PLUMBAGO_REFERENCE_BOUND(id, output, ...) \
  [[maybe_unused]] static const bool registered_bound_##id = ::plumbago::reference::register_bound(output, __VA_ARGS__)
