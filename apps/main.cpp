// plumbago: render, compare, inspect. See README.md and docs/design.md.
#include <cstdio>
#include <exception>

#include "apps/command.hpp"
#include "common/util/memory_budget.hpp"
#include "common/util/output_file.hpp"
#include "parity/parity.hpp"

namespace plumbago {
std::vector<CommandSetup>& command_registry() {
  static std::vector<CommandSetup> registry;
  return registry;
}
}  // namespace plumbago

int main(int argc, char** argv) {
  plumbago::remove_outputs_on_interrupt();  // before any thread starts
  try {  // a stage declared wrong or implemented on one backend only: before any command runs
    plumbago::check_stage_registry();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "plumbago: stage registry: %s\n", e.what());
    return 3;
  }
  CLI::App app{"Plumbago: real-time pencil and sketch rendering, with a CPU reference for every stage"};
  app.require_subcommand(1);
  app.fallthrough();  // the global options may also follow the command
  app.add_option_function<double>("--memory-budget-gb", plumbago::set_memory_budget_gb,
                                  "The memory a command may plan to use, in GB (default " +
                                      std::to_string(int(plumbago::kDefaultMemoryBudgetGb)) +
                                      "): larger meshes, images and textures are refused (docs/bad-input.md)");
  for (auto setup : plumbago::command_registry()) setup(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::RuntimeError& e) {  // a command's verdict, e.g. compare: 1 = a stage failed
    return e.get_exit_code();
  } catch (const CLI::ParseError& e) {
    int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "plumbago: error: %s\n", e.what());
    return 2;
  }
  return 0;
}
