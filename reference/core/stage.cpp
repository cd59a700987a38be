#include "reference/core/stage.hpp"

#include <stdexcept>

#include "common/core/frame.hpp"
#include "common/sketchy/sketchy.hpp"

namespace plumbago::reference {

namespace {

std::map<std::string, StageFn>& registry() {
  static std::map<std::string, StageFn> stages;
  return stages;
}

std::map<std::string, BoundFn>& bounds() {
  static std::map<std::string, BoundFn> fns;
  return fns;
}

}  // namespace

ReferenceFrame::ReferenceFrame(const Scene& s, Preprocessed p, std::vector<std::string> st)
    : FrameData(std::move(p)),
      scene(s),
      ordinary(ordinary_objects(s)),
      sketchy(sketchy_objects(s)),
      stages(std::move(st)) {}

const Image* ReferenceFrame::get(Maybe<Buffer> buffer) const {
  checked(buffer.handle.name);
  auto it = images.find(buffer.handle.name);
  return it == images.end() ? nullptr : &it->second;
}

const Image& ReferenceFrame::get(Buffer buffer) const {
  if (const Image* img = get(maybe(buffer))) return *img;
  throw std::logic_error(std::string("reference frame: no stage made '") + buffer.name + "'");
}

void ReferenceFrame::put(Buffer buffer, Image image) {
  checked(buffer.name);
  images[buffer.name] = std::move(image);
}

const GBuffer* ReferenceFrame::get(Maybe<GBufferSlot> gbuffer) const {
  checked(gbuffer.handle.name);
  auto it = gbuffers.find(gbuffer.handle.name);
  return it == gbuffers.end() ? nullptr : &it->second;
}

const GBuffer& ReferenceFrame::get(GBufferSlot gbuffer) const {
  if (const GBuffer* g = get(maybe(gbuffer))) return *g;
  throw std::logic_error(std::string("reference frame: no stage made the G-buffer '") + gbuffer.name + "'");
}

void ReferenceFrame::put(GBufferSlot gbuffer, GBuffer value) {
  checked(gbuffer.name);
  gbuffers[gbuffer.name] = std::move(value);
}

void run_stage(ReferenceFrame& f, const std::string& stage) {
  StageFn fn = implementation(stage);
  f.running = {stage};
  fn(f);
  f.running.clear();
}

bool register_stage(const char* stage, StageFn fn) {
  if (!is_stage(stage))
    throw std::logic_error(std::string("reference/: an implementation of unknown stage '") + stage + "'");
  if (!registry().emplace(stage, fn).second)
    throw std::logic_error(std::string("reference/: stage '") + stage + "' is registered twice");
  return true;
}

void check_implementations() {
  std::string missing;
  for (const StageDesc& s : stage_table())
    if (s.kind == StageKind::Frame && !registry().count(s.name)) missing += (missing.empty() ? "" : ", ") + s.name;
  if (!missing.empty())
    throw std::logic_error("the reference backend implements no stage " + missing +
                           " (register it in reference/<stem>.cpp)");
}

StageFn implementation(const std::string& stage) {
  check_implementations();
  find_stage(stage);  // an unknown name says which are known
  return registry().at(stage);
}

bool register_bound(const char* output, BoundFn fn) {
  find_output(output);  // throws for an undeclared output
  if (!bounds().emplace(output, fn).second)
    throw std::logic_error(std::string("reference/: a second bound for '") + output + "'");
  return true;
}

BoundFn find_bound(const std::string& output) {
  auto it = bounds().find(output);
  return it == bounds().end() ? nullptr : it->second;
}

std::map<std::string, Image> dump(const ReferenceFrame& f) {
  std::map<std::string, Image> all = f.images;
  for (const auto& [stage, g] : f.gbuffers) add_gbuffer_buffers(g, all, stage);
  std::map<std::string, Image> out;
  for (const std::string& name : dumped_buffers(f.stages, f.config())) {
    auto it = all.find(name);
    if (it == all.end())
      throw std::logic_error("reference: stage '" + stage_of(name).name + "' did not write '" + name + "'");
    out[name] = it->second;
  }
  return out;
}

}  // namespace plumbago::reference
