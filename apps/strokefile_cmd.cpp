// `plumbago strokefile SCENE drawing.svg -o strokes.json`: a stroke file (Kalnins et al. 2002, §3, §4.5,
// common/strokes/stroke_file.hpp) from strokes drawn in SVG over `plumbago render SCENE`'s image,
// with the scene's camera and resolution (common/strokes/svg_strokes.hpp says what is read).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "apps/command.hpp"
#include "apps/scene_options.hpp"
#include "common/strokes/svg_strokes.hpp"
#include "common/util/input_file.hpp"
#include "common/util/output_file.hpp"

namespace plumbago {
namespace {

struct StrokeFileOptions {
  SceneOptions scene;
  std::string svg, output = "strokes.json", role = "decal", style;
  int group = 0;
  bool free = false, mobile = false;
};

void run(const StrokeFileOptions& o) {
  Scene scene = o.scene.load();
  const std::vector<std::string>& roles = stroke_role_names();
  std::filesystem::path folder = std::filesystem::path(o.output).parent_path();
  SvgStrokeDefaults defaults{StrokeRole(std::find(roles.begin(), roles.end(), o.role) - roles.begin()),
                             o.style,
                             o.group,
                             o.free,
                             o.mobile,
                             folder.empty() ? "." : folder.string()};
  StrokeFile file;
  file.source = o.output;
  file.camera = scene.camera, file.width = scene.width, file.height = scene.height;
  file.style = o.style;
  file.strokes = svg_strokes(read_input_file(o.svg, "SVG drawing"), o.svg, scene.width, scene.height, defaults);
  if (file.strokes.empty()) throw std::invalid_argument(o.svg + ": no <polyline> or <path> to read");
  std::string text = stroke_file_json(file, scene.origin);
  parse_stroke_file(text, o.output, defaults.style_dir, scene.origin);  // what a scene would refuse: none left
  OutputFile out(o.output);
  std::ofstream(out.temporary_path()) << text;
  out.commit();
  std::printf("%zu strokes -> %s\n", file.strokes.size(), o.output.c_str());
}

void setup(CLI::App& app) {
  auto o = std::make_shared<StrokeFileOptions>();
  auto* cmd = app.add_subcommand("strokefile",
                                 "Make a stroke file (Kalnins et al. 2002, §3, §4.5) from an SVG drawn over the "
                                 "scene's render");
  o->scene.add_to(cmd, true);
  cmd->add_option("svg", o->svg, "the drawing: <polyline> and straight <path> elements over the rendered PNG")
      ->required();
  cmd->add_option("-o,--output", o->output, "the stroke file to write")->capture_default_str();
  cmd->add_option("--role", o->role, "the strokes' role where an element has no data-role")
      ->check(CLI::IsMember(stroke_role_names()))
      ->capture_default_str();
  cmd->add_option("--style", o->style,
                  "the stroke style (preset or file) of decals and hatching where an element has no data-style");
  cmd->add_option("--group", o->group, "hatching: the group where an element has no data-group")->capture_default_str();
  cmd->add_flag("--free", o->free,
                "hatching: a free group (Kalnins et al. 2002, §6) where an element has no "
                "data-free");
  cmd->add_flag("--mobile", o->mobile,
                "hatching: a mobile group (Kalnins et al. 2002, §6.3) where an element has no data-mobile");
  cmd->callback([o] { run(*o); });
}

PLUMBAGO_COMMAND(setup);

}  // namespace
}  // namespace plumbago
