// Options every scene-taking command shares: the scene (a file, "builtin:NAME", or none
// for the default built-in scene), --size and --set.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <vector>

#include "common/scene/scene.hpp"

namespace plumbago {

struct SceneOptions {
  std::string scene;  // empty: the default built-in scene
  std::string size;   // "WxH"
  std::vector<std::string> assignments;

  void add_to(CLI::App* cmd, bool scene_required);
  // Loads the scene and applies --size and --set; throws with the offending key or file.
  Scene load() const;
};

}  // namespace plumbago
