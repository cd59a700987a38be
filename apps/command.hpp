// Sub-commands of the `plumbago` program. Each apps/<name>_cmd.cpp registers itself:
//   static void setup(CLI::App& app) { auto* cmd = app.add_subcommand(...); ... }
//   PLUMBAGO_COMMAND(setup);
// A command reports bad input by throwing; main() prints the message on stderr and
// exits with code 2 (docs/design.md, principle 7).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <vector>

namespace plumbago {

using CommandSetup = void (*)(CLI::App&);
std::vector<CommandSetup>& command_registry();
inline bool register_command(CommandSetup setup) {
  command_registry().push_back(setup);
  return true;
}

}  // namespace plumbago

#define PLUMBAGO_COMMAND_CAT(a, b) a##b
#define PLUMBAGO_COMMAND_NAME(a, b) PLUMBAGO_COMMAND_CAT(a, b)
#define PLUMBAGO_COMMAND(setup) \
  static const bool PLUMBAGO_COMMAND_NAME(plumbago_registered_, __LINE__) = ::plumbago::register_command(setup)
