#include "gpu/core/stage.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "common/scene/animation.hpp"
#include "common/sketchy/sketchy.hpp"
#include "common/sketchy/sketchy_gbuffer.hpp"

namespace plumbago::gpu {

namespace {

std::vector<GpuPassDef>& registry() {
  static std::vector<GpuPassDef> passes;
  return passes;
}

bool contains(const std::vector<std::string>& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

PixelRect bounding(const PixelRect& a, const PixelRect& b) {
  if (a.x1 <= a.x0 || a.y1 <= a.y0) return b;
  if (b.x1 <= b.x0 || b.y1 <= b.y0) return a;
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

}  // namespace

GpuFrame::GpuFrame(const Scene& s, const Preprocessed& p, std::vector<std::string> st)
    : FrameData(p), scene(s), ordinary(ordinary_objects(s)), sketchy(sketchy_objects(s)), stages(std::move(st)) {}

PixelRect GpuFrame::filter_rect(int radius) const {
  if (!ordinary_bounds_) ordinary_bounds_ = window_bounds(ordinary, ordinary.width, ordinary.height);
  return plumbago::filter_rect(*ordinary_bounds_, ordinary, radius);
}

void GpuFrame::camera_moved() {
  take_view(ordinary, scene);
  take_view(sketchy, scene);
  ordinary_bounds_.reset();
}

bool GpuFrame::ran(const std::string& stage) const {
  find_stage(stage);  // an unknown name is a mistake, not a stage that did not run
  return contains(stages, stage);
}

Texture& GpuFrame::texture_named(const std::string& name) {
  const Output& declared = find_output(name);
  if (std::string under = drawn_over(declared, stages); !under.empty()) return texture_named(under);
  auto it = textures_.find(name);
  if (it == textures_.end())
    it = textures_.emplace(name, make_texture(scene.width, scene.height, texture_format(declared))).first;
  return it->second;
}

Texture& GpuFrame::put(plumbago::Buffer buffer) {
  checked(buffer.name);
  return texture_named(buffer.name);
}

void GpuFrame::put(plumbago::Buffer buffer, Texture texture) { textures_[buffer.name] = std::move(texture); }

const Texture* GpuFrame::get(Maybe<plumbago::Buffer> buffer) const {
  checked(buffer.handle.name);
  auto it = textures_.find(buffer.handle.name);
  return it == textures_.end() ? nullptr : &it->second;
}

const Texture& GpuFrame::get(plumbago::Buffer buffer) const {
  if (const Texture* t = get(maybe(buffer))) return *t;
  throw std::logic_error(std::string("GPU frame: no pass wrote '") + buffer.name + "'");
}

void GpuFrame::put(GBufferSlot gbuffer, const GBufferTargets& targets) { shared_[gbuffer.name] = &targets; }

const GBufferTargets& GpuFrame::get(GBufferSlot gbuffer) const {
  checked(gbuffer.name);
  auto it = shared_.find(gbuffer.name);
  if (it == shared_.end())
    throw std::logic_error(std::string("GPU frame: no pass made the G-buffer '") + gbuffer.name + "'");
  return *std::any_cast<const GBufferTargets*>(it->second);
}

void GpuFrame::read_gbuffer(const std::string& stage, const GBufferChannels& c) {
  auto [it, first] = gbuffer_reads_.emplace(stage, GBufferChannels::none());
  GBufferChannels& r = it->second;
  r.normal |= c.normal;
  r.face_normal |= c.face_normal;
  r.bary |= c.bary;
  r.gouraud |= c.gouraud;
  r.theta_min |= c.theta_min;
  r.theta_max |= c.theta_max;
  r.depth |= c.depth;
  r.triangle_angles |= c.triangle_angles;
  r.object_only_background |= c.object_only_background;
  r.read_region = bounding(r.read_region, c.read_region);
}

void GpuFrame::read_region(GBufferSlot gbuffer, PixelRect region) {
  GBufferChannels c = GBufferChannels::none();
  c.read_region = region;
  read_gbuffer(gbuffer.name, c);
}

void GpuFrame::read_near_objects(GBufferSlot gbuffer, int radius) {
  read_region(gbuffer, PixelRect{});  // the channels' entry, its region made per camera
  int& r = gbuffer_radii_.emplace(gbuffer.name, radius).first->second;
  r = std::max(r, radius);
}

GBufferChannels GpuFrame::gbuffer_channels(const std::string& stage) const {
  if (dump) return {};
  auto it = gbuffer_reads_.find(stage);
  if (it == gbuffer_reads_.end()) return GBufferChannels::none();
  GBufferChannels c = it->second;
  if (auto r = gbuffer_radii_.find(stage); r != gbuffer_radii_.end())
    c.read_region = bounding(c.read_region, filter_rect(r->second));
  return c;
}

void GpuPass::dump(GpuFrame& f, const std::vector<std::string>& stages, std::map<std::string, Image>& out) {
  for (const std::string& name : stages) {
    const StageDesc& stage = find_stage(name);
    for (const Output* o : outputs_written(stage, f.config()))
      if (o->texel != Texel::Host)
        out[stage.output_name(*o)] = download_texture(f.texture_named(stage.output_name(*o)), o->channels);
  }
}

namespace {

// The targets of `g` that `stages` read, from the channels they declare as inputs. Where
// they are kept (gpu/scene/gbuffer.hpp): the linear depth rides in the w of a normal target
// (its own target only for a pass that reads no normals), the Gouraud intensity in the
// barycentrics' w, the corner angles in TriangleAngles; an input the GPU reads in another
// form (fed_in_parity false: the sketchy sprite tests the depth buffer) reads no target.
GBufferChannels channels_read(const GBufferSlot& g, const std::vector<std::string>& stages, const StageConfig& c) {
  auto reads = [&](plumbago::Buffer channel) {
    for (const std::string& s : stages)
      for (const Input& in : find_stage(s).inputs)
        if (in.buffer() == channel.name && in.fed_in_parity && (!in.used || in.used(c))) return true;
    return false;
  };
  GBufferChannels r = GBufferChannels::none();
  r.normal = reads(g.normal);
  r.face_normal = reads(g.face_normal);
  r.bary = reads(g.bary) || reads(g.gouraud);
  r.triangle_angles = reads(g.theta_min) || reads(g.theta_max);
  r.depth = reads(g.depth) && !r.normal && !r.face_normal;
  return r;
}

}  // namespace

std::unique_ptr<GpuPass> make_checked(const GpuPassDef& def, GpuFrame& f) {
  for (const GBufferSlot& g : {kGBuffer, kSketchyGBuffer})
    f.read_gbuffer(g.name, channels_read(g, def.stages, f.config()));
  f.running = def.stages;
  std::unique_ptr<GpuPass> pass = def.make(f);
  f.running.clear();
  return pass;
}

void run_checked(const GpuPassDef& def, GpuPass& pass, GpuFrame& f) {
  f.running = def.stages;
  pass.run(f);
  f.running.clear();
}

Probe probe_of(const std::string& pass) {
  if (pass == "readback") return Probe::Readback;
  for (const GpuPassDef& p : registry())
    if (p.name() == pass) return p.probe;
  return Probe::Fullscreen;
}

std::string GpuPassDef::name() const {
  std::string n;
  for (const std::string& s : stages) n += (n.empty() ? "" : "+") + s;
  return n;
}

bool register_pass(GpuPassDef def) {
  for (const std::string& s : def.stages)
    if (!is_stage(s)) throw std::logic_error("gpu/: a pass computes unknown stage '" + s + "'");
  for (const std::string& o : def.skipped) {
    find_output(o);
    if (!contains(def.stages, stage_of(o).name))
      throw std::logic_error("gpu/: pass " + def.name() + " skips '" + o + "', which none of its stages writes");
  }
  for (const GpuPassDef& p : registry())
    if (p.stages == def.stages) throw std::logic_error("gpu/: pass " + def.name() + " is registered twice");
  registry().push_back(std::move(def));
  return true;
}

const std::vector<GpuPassDef>& registered_passes() { return registry(); }

void check_implementations() {
  std::string missing;
  for (const StageDesc& s : stage_table()) {
    bool computed = std::any_of(registry().begin(), registry().end(),
                                [&](const GpuPassDef& p) { return contains(p.stages, s.name); });
    if (s.kind == StageKind::Frame && !computed) missing += (missing.empty() ? "" : ", ") + s.name;
  }
  if (!missing.empty())
    throw std::logic_error("the GPU backend implements no stage " + missing + " (register a pass in gpu/<stem>.cpp)");
}

std::vector<const GpuPassDef*> plan_passes(const std::vector<std::string>& stages, const StageConfig& config) {
  check_implementations();
  std::vector<std::pair<size_t, const GpuPassDef*>> planned;  // where the pass's last stage is
  std::set<std::string> covered;
  for (const std::string& s : stages) {
    if (covered.count(s)) continue;
    const GpuPassDef* best = nullptr;
    for (const GpuPassDef& p : registry()) {
      bool all_run =
          std::all_of(p.stages.begin(), p.stages.end(), [&](const std::string& m) { return contains(stages, m); });
      if (contains(p.stages, s) && all_run && (!best || p.stages.size() > best->stages.size())) best = &p;
    }
    if (!best)
      throw std::logic_error("the GPU backend computes stage '" + s +
                             "' only fused with stages this frame does not run");
    size_t last = 0;
    for (const std::string& m : best->stages) {
      covered.insert(m);
      last = std::max(last, size_t(std::find(stages.begin(), stages.end(), m) - stages.begin()));
    }
    for (const std::string& skipped : best->skipped)
      for (const std::string& reader : stages)
        if (!contains(best->stages, reader) && contains(inputs_read(find_stage(reader), config), skipped))
          throw std::logic_error("stage '" + reader + "' reads '" + skipped + "', which GPU pass " + best->name() +
                                 " does not write in a frame");
    planned.push_back({last, best});
  }
  std::stable_sort(planned.begin(), planned.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<const GpuPassDef*> out;
  for (const auto& p : planned) out.push_back(p.second);
  return out;
}

const Texture& table_target(GpuFrame& f, size_t records, plumbago::Buffer table) {
  if (const Texture* made = f.get(maybe(table))) return *made;
  auto [width, height] = table_size(records);
  GLint largest = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &largest);
  if (height > largest)
    throw std::runtime_error(std::string(table.name) + ": " + std::to_string(records) + " records take " +
                             std::to_string(height) + " rows of " + std::to_string(kTableRow) +
                             ", over this GL's largest texture (" + std::to_string(largest) + " rows): at most " +
                             std::to_string(size_t(largest) * kTableRow) + " records");
  f.put(table, make_texture(width, height, texture_format(find_output(table.name))));
  return f.get(table);
}

GLenum texture_format(const Output& o) {
  switch (o.texel) {
    case Texel::Unorm8:
      return GL_RGBA8;
    case Texel::Uint:
      return o.channels == 1 ? GL_R32UI : GL_RG32UI;
    case Texel::Float:
      return o.channels == 1 ? GL_R32F : o.channels == 2 ? GL_RG32F : GL_RGBA32F;
    case Texel::Host:
      break;
  }
  throw std::logic_error("'" + o.buffer() + "' is CPU data, not a GPU texture");
}

}  // namespace plumbago::gpu
