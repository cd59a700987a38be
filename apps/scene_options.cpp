#include "apps/scene_options.hpp"

#include <regex>
#include <stdexcept>

#include "common/scene/open_scene.hpp"
#include "common/util/memory_budget.hpp"

namespace plumbago {

void SceneOptions::add_to(CLI::App* cmd, bool scene_required) {
  std::string builtins;
  for (const std::string& name : builtin_scene_names()) builtins += (builtins.empty() ? "" : ", ") + name;
  auto* opt = cmd->add_option("scene", scene, "Scene file (JSON), or builtin:NAME (" + builtins + ")");
  if (scene_required) opt->required();
  cmd->add_option("--size", size, "Image size WxH (overrides the scene's resolution)");
  cmd->add_option("--set", assignments, "Override a parameter: stage.name=value (see `plumbago params`)");
}

namespace {

void apply_size(const std::string& size, Scene& scene) {
  std::smatch m;
  if (!std::regex_match(size, m, std::regex(R"((\d{1,5})x(\d{1,5}))")))
    throw std::invalid_argument("--size: '" + size + "' is not WxH (e.g. 800x800)");
  resize_scene(scene, std::stoi(m[1]), std::stoi(m[2]), "--size");
}

}  // namespace

Scene SceneOptions::load() const {
  Scene s = open_scene(scene);
  if (!size.empty()) apply_size(size, s);
  for (const auto& a : assignments) {
    try {
      s.params.set_assignment(a);
    } catch (const ParamError& e) {
      throw ParamError(std::string("--set: ") + e.what());
    }
  }
  check_scene_memory(s);  // before any buffer is made
  return s;
}

}  // namespace plumbago
