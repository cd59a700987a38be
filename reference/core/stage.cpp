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
    : scene(s), ordinary(ordinary_objects(s)), sketchy(sketchy_objects(s)), pre(std::move(p)), stages(std::move(st)) {}

const Image* ReferenceFrame::find(const std::string& name) const {
  auto it = images.find(name);
  return it == images.end() ? nullptr : &it->second;
}

const Image& ReferenceFrame::image(const std::string& name) const {
  if (const Image* img = find(name)) return *img;
  throw std::logic_error("reference frame: no stage made '" + name + "'");
}

const GBuffer& ReferenceFrame::gbuffer(const std::string& stage) const {
  auto it = gbuffers.find(stage);
  if (it == gbuffers.end()) throw std::logic_error("reference frame: no stage made the G-buffer '" + stage + "'");
  return it->second;
}

bool register_stage(const char* stage, StageFn fn) {
  if (!is_stage(stage)) throw std::logic_error(std::string("reference/: an implementation of unknown stage '") + stage + "'");
  if (!registry().emplace(stage, fn).second)
    throw std::logic_error(std::string("reference/: stage '") + stage + "' is registered twice");
  return true;
}

void check_implementations() {
  std::string missing;
  for (const StageDesc& s : stage_table())
    if (s.kind == StageKind::Frame && !registry().count(s.name)) missing += (missing.empty() ? "" : ", ") + s.name;
  if (!missing.empty())
    throw std::logic_error("the reference backend implements no stage " + missing + " (register it in reference/<stem>.cpp)");
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
    if (it == all.end()) throw std::logic_error("reference: stage '" + stage_of(name).name + "' did not write '" + name + "'");
    out[name] = it->second;
  }
  return out;
}

}  // namespace plumbago::reference
