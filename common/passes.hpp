// The pass table (DESIGN.md principle 2): each effect names the passes it needs, each
// pass names the passes it reads from; the pipeline runs exactly the closure, in table
// order, on either backend.
#pragma once

#include <string>
#include <vector>

#include "common/params.hpp"

namespace plumbago {

enum class PassKind { Preprocessing, Stage };

struct PassDef {
  std::string name;
  PassKind kind;
  std::vector<std::string> needs;  // passes whose outputs this one reads
  std::string doc;
  bool (*wanted)(const ParamSet&) = nullptr;  // when set, the pass runs only where this holds
};

struct EffectDef {
  std::string name;
  std::vector<std::string> passes;
  std::string doc;
};

// Every pass, in an order where each comes after what it needs.
const std::vector<PassDef>& pass_table();
const std::vector<EffectDef>& effect_table();
bool is_effect(const std::string& name);
std::string effect_names();  // "contours, ..." for messages

// The passes `effects` need with `params`, dependencies included, in table order.
// Throws std::invalid_argument naming an unknown effect.
std::vector<std::string> passes_for(const std::vector<std::string>& effects, const ParamSet& params = {});

bool is_preprocessing(const std::string& pass);

// The per-frame stages among `passes` (preprocessing left out).
std::vector<std::string> frame_stages(const std::vector<std::string>& passes);

}  // namespace plumbago
