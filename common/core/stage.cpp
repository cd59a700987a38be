#include "common/core/stage.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "common/core/stage_registry.hpp"

namespace plumbago {

bool StageConfig::has(const char* effect) const {
  return std::find(effects.begin(), effects.end(), effect) != effects.end();
}

namespace when {
bool effect_contours(const StageConfig& c) { return c.has("contours"); }
bool effect_interior(const StageConfig& c) { return c.has("interior") || c.has("crosshatch"); }
bool effect_paper(const StageConfig& c) { return c.has("paper"); }
bool pencil_effects(const StageConfig& c) { return effect_contours(c) || effect_interior(c) || effect_paper(c); }
bool effect_sketchy(const StageConfig& c) { return c.has("sketchy"); }
bool ordinary_drawn(const StageConfig& c) { return pencil_effects(c) || c.has("strokes"); }
bool effect_basecoat(const StageConfig& c) { return c.has("basecoat"); }
}  // namespace when

namespace {

template <class... Stages>
std::vector<StageDesc> describe_all(TypeList<Stages...>) {
  return {Stages::describe()...};
}

const Output* output_in(const StageDesc& stage, const std::string& name) {
  for (const Output& o : stage.outputs)
    if (o.name() == name) return &o;
  return nullptr;
}

// The registry's rules: a mistake in a descriptor is an error at start-up, not a skip.
void check(const std::vector<StageDesc>& table) {
  std::set<std::string> seen, prefixes, effects;
  for (const StageDesc& s : table)
    for (const EffectDef& e : s.declared_effects)
      if (!effects.insert(e.name).second) throw std::logic_error("effect '" + e.name + "' is declared twice");
  for (const ParamSpec& p : param_specs()) prefixes.insert(p.key.substr(0, p.key.find('.')));
  for (const StageDesc& s : table) {
    auto fail = [&](const std::string& what) { throw std::logic_error("stage '" + s.name + "': " + what); };
    for (const Input& in : s.inputs) {
      size_t dot = in.buffer().find('.');
      std::string producer = in.buffer().substr(0, dot);
      if (dot == std::string::npos || !seen.count(producer))
        fail("reads '" + in.buffer() + "', which no earlier stage declares");
      const StageDesc& from =
          *std::find_if(table.begin(), table.end(), [&](const StageDesc& d) { return d.name == producer; });
      if (!output_in(from, in.buffer().substr(dot + 1)))
        fail("reads '" + in.buffer() + "', which '" + producer + "' does not write");
    }
    for (const Output& o : s.outputs)
      if (o.producer() != s.name) fail("declares '" + o.buffer() + "', another stage's handle");
    for (const std::string& e : s.effects)
      if (!effects.count(e)) fail("names an unknown effect '" + e + "'");
    for (const std::string& p : s.params)
      if (!prefixes.count(p)) fail("reads parameters '" + p + ".*', which no stage declares");
    if ((s.kind == StageKind::Preprocessing) != (s.preprocess != nullptr))
      fail("preprocessing and only preprocessing has an implementation in its descriptor");
    if (!seen.insert(s.name).second) fail("declared twice");
  }
}

}  // namespace

const std::vector<StageDesc>& stage_table() {
  static const std::vector<StageDesc> table = [] {
    std::vector<StageDesc> t = describe_all(AllStages{});
    check(t);
    return t;
  }();
  return table;
}

namespace {

bool declares(const StageDesc& s, const std::string& buffer) {
  auto named = [&](const std::string& name) { return name == buffer || name.rfind(buffer + ".", 0) == 0; };
  for (const Input& in : s.inputs)
    if (named(in.buffer())) return true;
  for (const Output& o : s.outputs)
    if (named(s.output_name(o))) return true;
  return false;
}

}  // namespace

void check_declared(const std::vector<std::string>& stages, const std::string& buffer) {
  for (const std::string& s : stages)
    if (declares(find_stage(s), buffer)) return;
  std::string names;
  for (const std::string& s : stages) names += (names.empty() ? "" : "+") + s;
  throw std::logic_error("stage " + names + " reads '" + buffer + "', which it does not declare");
}

bool is_stage(const std::string& name) {
  const auto& t = stage_table();
  return std::any_of(t.begin(), t.end(), [&](const StageDesc& s) { return s.name == name; });
}

std::string stage_names() {
  std::string names;
  for (const auto& s : stage_table()) names += (names.empty() ? "" : ", ") + s.name;
  return names;
}

const StageDesc& find_stage(const std::string& name) {
  for (const auto& s : stage_table())
    if (s.name == name) return s;
  throw std::invalid_argument("unknown stage '" + name + "' (known: " + stage_names() + ")");
}

const StageDesc& stage_of(const std::string& buffer) { return find_stage(buffer.substr(0, buffer.find('.'))); }

const Output& find_output(const std::string& buffer) {
  size_t dot = buffer.find('.');
  const Output* o = dot == std::string::npos ? nullptr : output_in(stage_of(buffer), buffer.substr(dot + 1));
  if (!o) throw std::invalid_argument("no stage writes a buffer '" + buffer + "'");
  return *o;
}

std::vector<std::string> inputs_read(const StageDesc& stage, const StageConfig& config) {
  std::vector<std::string> read;
  for (const Input& in : stage.inputs)
    if (!in.used || in.used(config)) read.push_back(in.buffer());
  return read;
}

std::vector<const Output*> outputs_written(const StageDesc& stage, const StageConfig& config) {
  std::vector<const Output*> written;
  for (const Output& o : stage.outputs)
    if (!o.written || o.written(config)) written.push_back(&o);
  return written;
}

std::vector<std::string> dumped_buffers(const std::vector<std::string>& stages, const StageConfig& config) {
  std::set<std::string> drawn_over;
  for (const std::string& name : stages)
    for (const Output& o : find_stage(name).outputs)
      if (std::string under = plumbago::drawn_over(o, stages); !under.empty()) drawn_over.insert(under);
  std::vector<std::string> names;
  for (const std::string& name : stages) {
    const StageDesc& stage = find_stage(name);
    if (stage.kind != StageKind::Frame) continue;
    for (const Output* o : outputs_written(stage, config))
      if (o->texel != Texel::Host && !drawn_over.count(stage.output_name(*o))) names.push_back(stage.output_name(*o));
  }
  return names;
}

std::string drawn_over(const Output& output, const std::vector<std::string>& stages) {
  for (const std::string& under : output.draws_over)
    if (std::find(stages.begin(), stages.end(), stage_of(under).name) != stages.end()) return under;
  return {};
}

std::string frame_color_buffer(const std::vector<std::string>& stages) {
  std::string color;
  for (const std::string& name : stages)
    for (const Output& o : find_stage(name).outputs)
      if (o.frame_color) color = o.buffer();
  return color;
}

}  // namespace plumbago
