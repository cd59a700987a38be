// plumbago compare SCENE [--stages all|a,b] [--json] [--out DIR]
// Exit code 0 when every stage passes, 1 when one fails, 2 on bad input.
#include <cstdio>
#include <filesystem>

#include "apps/command.hpp"
#include "apps/scene_options.hpp"
#include "common/util/visualize.hpp"
#include "parity/parity.hpp"

namespace plumbago {
namespace {

struct CompareOptions {
  SceneOptions scene;
  std::vector<std::string> stages;
  std::string out_dir;
  bool json = false;
};

// Every target is checked before the first is written; all are put in place together.
void write_images(const std::vector<StageParity>& results, const std::string& dir, OutputFiles& out) {
  ImageFiles files;
  for (const auto& s : results) {
    std::string base = (std::filesystem::path(dir) / s.name).string();
    files.emplace_back(base + ".reference.png", [&s] { return viewable(s.name, s.reference); });
    files.emplace_back(base + ".gpu.png", [&s] { return viewable(s.name, s.gpu); });
    files.emplace_back(base + ".diff.png", [&s] { return diff_heatmap(s.reference, s.gpu, s.diff.tolerance); });
  }
  write_images(files, out);
  out.commit();
}

void print(const std::vector<StageParity>& results, bool all_pass, bool json) {
  if (json) {
    std::printf("%s\n", parity_report(results).dump(2).c_str());
    return;
  }
  for (const auto& s : results)
    std::printf("%s  %s  [%s]\n", s.pass ? "PASS" : "FAIL", format_diff(s.name, s.diff).c_str(), s.note.c_str());
  std::printf("%s\n", all_pass ? "all stages agree" : "some stages disagree");
}

void run(const CompareOptions& o) {
  Scene scene = o.scene.load();
  OutputFiles out;
  if (!o.out_dir.empty()) out.folder(o.out_dir);
  std::vector<std::string> stages = o.stages;
  if (stages.size() == 1 && stages[0] == "all") stages.clear();
  auto results = run_parity(scene, stages);
  bool all_pass = std::all_of(results.begin(), results.end(), [](const StageParity& s) { return s.pass; });
  if (!o.out_dir.empty()) write_images(results, o.out_dir, out);
  print(results, all_pass, o.json);
  if (!all_pass) throw CLI::RuntimeError(1);
}

void setup(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  auto* cmd = app.add_subcommand("compare", "Run each stage on both backends with the same inputs and compare");
  o->scene.add_to(cmd, true);
  cmd->add_option("--stages", o->stages, "all, or a comma-separated list of stages")->delimiter(',');
  cmd->add_flag("--json", o->json, "One JSON object: {pass, stages: [{name, pass, max_abs, rmse, ...}]}");
  cmd->add_option("--out", o->out_dir, "Write each stage's reference, gpu and heat-map images into DIR");
  cmd->callback([o] { run(*o); });
}

PLUMBAGO_COMMAND(setup);

}  // namespace
}  // namespace plumbago
