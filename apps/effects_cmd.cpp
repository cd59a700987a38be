// plumbago effects: every effect a scene can ask for, its doc, and the stages it runs
// (common/core/passes.hpp passes_for, with the default parameters).
#include <algorithm>
#include <cstdio>

#include "apps/command.hpp"
#include "common/core/passes.hpp"

namespace plumbago {
namespace {

void print_effects() {
  int width = 0;  // the longest name's
  for (const EffectDef& e : effect_table()) width = std::max(width, int(e.name.size()));
  for (const EffectDef& e : effect_table()) {
    std::string stages;
    for (const std::string& s : passes_for({e.name})) stages += (stages.empty() ? "" : " ") + s;
    std::printf("%-*s %s\n%-*s runs: %s\n", width, e.name.c_str(), e.doc.c_str(), width, "", stages.c_str());
  }
}

void setup(CLI::App& app) {
  auto* cmd = app.add_subcommand("effects", "List every effect a scene can ask for, and the stages each runs");
  cmd->callback(print_effects);
}

PLUMBAGO_COMMAND(setup);

}  // namespace
}  // namespace plumbago
