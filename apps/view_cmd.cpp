// plumbago view [SCENE] [--size WxH] [--set k=v ...] [--frames N --screenshot FILE] [--no-ui] [--script FILE]
#include "apps/command.hpp"
#include "apps/viewer/viewer.hpp"

namespace plumbago {
namespace {

void run(const ViewerOptions& o) {
#if PLUMBAGO_VIEWER
  run_viewer(o);
#else
  (void)o;
  throw std::runtime_error(
      "view: this plumbago was built without the viewer, which needs GLFW and Dear ImGui "
      "(Debian packages 'libglfw3-dev libimgui-dev', scripts/install-deps.sh) and the EGL "
      "build; cmake says which was missing");
#endif
}

void setup(CLI::App& app) {
  auto o = std::make_shared<ViewerOptions>();
  auto* cmd = app.add_subcommand("view",
                                 "Open a window on a scene (default: builtin:pencil, the CAD part with every pencil "
                                 "effect): orbit, turn every parameter, time the passes");
  o->scene.add_to(cmd, false);
  auto* frames = cmd->add_option("--frames", o->frames, "Draw N frames, write --screenshot and exit")
                     ->check(CLI::Range(1, 100000));
  cmd->add_option("--screenshot", o->screenshot, "With --frames: PNG of what the window shows")->needs(frames);
  cmd->add_flag("--no-ui", o->no_ui, "Show the frame alone, without the panels");
  cmd->add_option("--script", o->script,
                  "JSON list of actions applied in order (set, effect, orbit, stage, check, heatmap, save, "
                  "screenshot: docs/viewer.md); with --frames, the viewer exits when it ran to its end");
  cmd->callback([o] { run(*o); });
}

PLUMBAGO_COMMAND(setup);

}  // namespace
}  // namespace plumbago
