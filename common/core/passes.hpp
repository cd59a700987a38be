// What runs for a scene (docs/design.md, principle 2): each effect asks for the stages whose
// descriptors name it, each stage for the stages whose outputs it reads
// (common/core/stage.hpp); the pipeline runs exactly that closure, in registry order, on
// either backend.
#pragma once

#include <string>
#include <vector>

#include "common/core/params.hpp"
#include "common/core/stage.hpp"

namespace plumbago {

// Every effect, as the stages declare them (common/core/stage.hpp), in registry order.
const std::vector<EffectDef>& effect_table();
bool is_effect(const std::string& name);
std::string effect_names();  // "contours, ..." for messages

// The stages `effects` need with `params`, what they read included, in registry order.
// Throws std::invalid_argument naming an unknown effect.
std::vector<std::string> passes_for(const std::vector<std::string>& effects, const ParamSet& params = {});

bool is_preprocessing(const std::string& pass);
// The passes among `passes` that read the parameters of `key` ("stage.name", or the
// prefix "stage" alone): their descriptors name the prefix.
std::vector<std::string> passes_reading(const std::vector<std::string>& passes, const std::string& key);
// Whether a preprocessing step among `passes` reads the parameter `key`.
bool preprocessing_reads(const std::vector<std::string>& passes, const std::string& key);

// The per-frame stages among `passes` (preprocessing left out).
std::vector<std::string> frame_stages(const std::vector<std::string>& passes);

}  // namespace plumbago
