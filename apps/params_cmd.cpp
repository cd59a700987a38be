// plumbago params [STAGE]: every parameter with its default, valid range and doc.
#include <cstdio>
#include <stdexcept>

#include "apps/command.hpp"
#include "common/core/param_text.hpp"
#include "common/core/params.hpp"

namespace plumbago {
namespace {

void print_params(const std::string& stage) {
  bool any = false;
  for (const auto& s : param_specs()) {
    if (!stage.empty() && s.key.rfind(stage + ".", 0) != 0) continue;
    any = true;
    std::printf("%-30s %-6s %-12s %-22s %s\n", s.key.c_str(), param_type_name(s.type),
                format_value(s, s.default_value).c_str(), param_range(s).c_str(), s.doc.c_str());
  }
  if (!any) throw std::invalid_argument("unknown stage '" + stage + "' (see `plumbago params`)");
}

void setup(CLI::App& app) {
  auto* cmd = app.add_subcommand("params", "List every parameter: name, type, default, range, doc");
  auto stage = std::make_shared<std::string>();
  cmd->add_option("stage", *stage, "Only this stage's parameters (e.g. edge)");
  cmd->callback([stage] { print_params(*stage); });
}

PLUMBAGO_COMMAND(setup);

}  // namespace
}  // namespace plumbago
