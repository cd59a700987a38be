// plumbago textures [--out DIR] [--seed N] [--size WxH] [--set k=v ...]
// Writes every generated texture as PNG to look at (compare the pencil layers with
// Lee et al. 2006, Fig. 4).
#include <cstdio>
#include <filesystem>

#include "apps/command.hpp"
#include "apps/scene_options.hpp"
#include "common/core/frame.hpp"
#include "common/pencil/textures.hpp"
#include "common/util/output_file.hpp"

namespace plumbago {
namespace {

struct TexturesOptions {
  std::string out_dir = "textures";
  uint32_t seed = 1;
  SceneOptions scene;  // --size (the window the offset grids cover) and --set
};

void run(const TexturesOptions& o) {
  Scene s = o.scene.load();
  OutputFiles out;  // every target checked before the first is written; all put in place together
  out.folder(o.out_dir);
  Stopwatch watch;
  auto gallery = texture_gallery(s.params, o.seed, s.width, s.height);
  double ms = watch.ms();
  ImageFiles files;
  for (const auto& [name, img] : gallery)
    files.emplace_back((std::filesystem::path(o.out_dir) / (name + ".png")).string(), [&img] { return img; });
  write_images(files, out);
  out.commit();
  std::printf("wrote %zu textures to %s (generated in %.0f ms)\n", gallery.size(), o.out_dir.c_str(), ms);
}

void setup(CLI::App& app) {
  auto o = std::make_shared<TexturesOptions>();
  auto* cmd = app.add_subcommand("textures",
                                 "Write every generated texture (pencil stack, paper, offsets, sketchy noise) as PNG");
  cmd->add_option("--out", o->out_dir, "Folder for the PNGs")->capture_default_str();
  cmd->add_option("--seed", o->seed, "Scene seed the textures are generated from")->capture_default_str();
  cmd->add_option("--size", o->scene.size, "Window size WxH the contour offset grids cover");
  cmd->add_option("--set", o->scene.assignments, "Override a parameter: stage.name=value");
  cmd->callback([o] { run(*o); });
}

PLUMBAGO_COMMAND(setup);

}  // namespace
}  // namespace plumbago
