// plumbago view: the interactive viewer (apps/viewer/, built when GLFW and Dear ImGui are
// found; docs/viewer.md). The window shows the frame of the same GPU pipeline as
// `plumbago render`, with panels for every parameter, effect and object style.
#pragma once

#include <string>

#include "apps/scene_options.hpp"

namespace plumbago {

struct ViewerOptions {
  SceneOptions scene;
  int frames = 0;          // > 0: render this many frames, write the screenshot, exit
  std::string screenshot;  // PNG of what the window shows after `frames` frames
  bool no_ui = false;      // the frame alone, without the panels
  std::string script;      // actions to apply (apps/viewer/script.hpp); with frames, run to its end
};

// Opens the window and runs until it is closed (or `frames` frames were drawn). Throws
// std::runtime_error when no window can be opened (no display), saying so.
void run_viewer(const ViewerOptions& options);

}  // namespace plumbago
