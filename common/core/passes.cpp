#include "common/core/passes.hpp"

#include <algorithm>
#include <iterator>
#include <set>
#include <stdexcept>

namespace plumbago {

const std::vector<EffectDef>& effect_table() {
  static const std::vector<EffectDef> table = [] {
    std::vector<EffectDef> t;
    for (const StageDesc& s : stage_table()) t.insert(t.end(), s.declared_effects.begin(), s.declared_effects.end());
    return t;
  }();
  return table;
}

bool is_effect(const std::string& name) {
  const auto& t = effect_table();
  return std::any_of(t.begin(), t.end(), [&](const EffectDef& e) { return e.name == name; });
}

std::string effect_names() {
  std::string names;
  for (const auto& e : effect_table()) names += (names.empty() ? "" : ", ") + e.name;
  return names;
}

namespace {

void add_with_inputs(const StageDesc& stage, const StageConfig& config, std::set<std::string>& chosen) {
  if (!chosen.insert(stage.name).second) return;
  for (const std::string& buffer : inputs_read(stage, config)) add_with_inputs(stage_of(buffer), config, chosen);
}

}  // namespace

std::vector<std::string> passes_for(const std::vector<std::string>& effects, const ParamSet& params) {
  for (const auto& effect : effects)
    if (!is_effect(effect))
      throw std::invalid_argument("unknown effect '" + effect + "' (known: " + effect_names() + ")");
  StageConfig config{params, effects};
  std::set<std::string> chosen;
  for (const StageDesc& stage : stage_table())
    for (const std::string& e : stage.effects)
      if (config.has(e.c_str())) add_with_inputs(stage, config, chosen);
  std::vector<std::string> ordered;
  for (const StageDesc& stage : stage_table())
    if (chosen.count(stage.name)) ordered.push_back(stage.name);
  return ordered;
}

bool is_preprocessing(const std::string& pass) {
  return is_stage(pass) && find_stage(pass).kind == StageKind::Preprocessing;
}

std::vector<std::string> passes_reading(const std::vector<std::string>& passes, const std::string& key) {
  std::string prefix = key.substr(0, key.find('.'));
  std::vector<std::string> out;
  std::copy_if(passes.begin(), passes.end(), std::back_inserter(out), [&](const std::string& p) {
    const std::vector<std::string>& read = find_stage(p).params;
    return std::find(read.begin(), read.end(), prefix) != read.end();
  });
  return out;
}

bool preprocessing_reads(const std::vector<std::string>& passes, const std::string& key) {
  std::vector<std::string> reading = passes_reading(passes, key);
  return std::any_of(reading.begin(), reading.end(), is_preprocessing);
}

std::vector<std::string> frame_stages(const std::vector<std::string>& passes) {
  std::vector<std::string> stages;
  for (const auto& p : passes)
    if (find_stage(p).kind == StageKind::Frame) stages.push_back(p);
  return stages;
}

}  // namespace plumbago
