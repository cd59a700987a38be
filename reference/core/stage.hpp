// Stages on the reference backend: each registers its implementation next to its code
// (reference/<stem>.cpp), a plain function that reads its inputs from a ReferenceFrame by
// their declared names (common/core/stage.hpp) and writes its outputs there:
//
//   PLUMBAGO_REFERENCE_STAGE(edge_detect, [](ReferenceFrame& f) {
//     f.put("edge_detect.contour_darkness", contour_darkness(f.gbuffer("gbuffer"), f.params<EdgeDetectParams>()));
//   });
#pragma once

#include <map>
#include <string>
#include <vector>

#include "common/scene/gbuffer.hpp"
#include "common/core/host_data.hpp"
#include "common/core/preprocess.hpp"
#include "common/scene/scene.hpp"
#include "common/core/stage.hpp"

namespace plumbago::reference {

// The buffers of one frame, by name. The G-buffers are kept whole, under their stage's
// name ("gbuffer", "sketchy_gbuffer"); every other output is an image "<stage>.<output>".
struct ReferenceFrame {
  ReferenceFrame(const Scene& scene, Preprocessed pre, std::vector<std::string> stages);

  const Scene& scene;
  Scene ordinary, sketchy;  // the objects each pipeline draws (common/sketchy/sketchy.hpp)
  Preprocessed pre;
  std::vector<std::string> stages;  // the frame stages that run
  std::map<std::string, Image> images;
  std::map<std::string, GBuffer> gbuffers;

  template <class P>
  P params() const {
    return scene.params.get<P>();
  }
  StageConfig config() const { return {scene.params, scene.effects}; }
  // An input; throws std::logic_error naming it when no stage made it.
  const Image& image(const std::string& name) const;
  const GBuffer& gbuffer(const std::string& stage) const;
  // An optional input (an input whose condition may not hold): null when not made.
  const Image* find(const std::string& name) const;
  void put(const std::string& name, Image image) { images[name] = std::move(image); }
  HostData host;  // CPU data the stages share (common/core/host_data.hpp)
};

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

#define PLUMBAGO_REFERENCE_STAGE(stem, ...) \
  [[maybe_unused]] static const bool registered_reference_##stem = ::plumbago::reference::register_stage(#stem, __VA_ARGS__)
#define PLUMBAGO_REFERENCE_BOUND(id, output, ...) \
  [[maybe_unused]] static const bool registered_bound_##id = ::plumbago::reference::register_bound(output, __VA_ARGS__)
