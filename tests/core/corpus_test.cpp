// The malformed-input corpus (tests/corpus/, docs/bad-input.md): every entry of
// tests/corpus/expected.json run through the CLI on both backends (an SVG drawing through
// `plumbago strokefile`, once), each run under a time and a memory limit. An entry is
// refused (exit code 2, a message naming the file and where in it, nothing left behind)
// or rendered (exit code 0, no NaN or Inf in the image nor in any buffer or file the run
// writes).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "common/util/image.hpp"
#include "common/util/input_file.hpp"
#include "tests/support/cli_run.hpp"

namespace plumbago {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kCorpus = fs::path(PLUMBAGO_SOURCE_DIR) / "tests" / "corpus";
// The keys that name an input file, each the folder of the corpus that holds such files.
const char* const kInputKeys[] = {"mesh", "scene", "svg", "strokes", "style"};

// Each run's limits: far above what a 64x48 render of an entry takes (under 1 s; the GPU
// backend on llvmpipe reserves 1-2 GB of address space on 2 cores, more with more
// threads), far below what a hang or a runaway allocation reaches (the pencil stack at
// its largest took 14 GB and minutes). A run over them is killed and fails its entry.
constexpr int kSeconds = 60;
constexpr long long kAddressSpaceBytes = 6LL << 30;

std::string limited() {
  return "timeout -s KILL " + std::to_string(kSeconds) + " prlimit --as=" + std::to_string(kAddressSpaceBytes) + " ";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

bool has_word_nan_or_inf(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text.find("nan") != std::string::npos || text.find("inf") != std::string::npos;
}

json corpus_manifest() {
  std::ifstream in(kCorpus / "expected.json");
  return json::parse(in);
}

// What an entry feeds the program: the key of its input file, or "args".
std::string input_kind(const json& entry) {
  for (const char* key : kInputKeys)
    if (entry.contains(key)) return key;
  return "args";
}

// One shard per kind of input (a parameter), so that each runs within ctest's time limit
// on a slow machine and the shards run side by side.
class Corpus : public ::testing::TestWithParam<std::string> {
 protected:
  Corpus() : manifest_(corpus_manifest()) {
    fs::create_directories(out_);
    fs::create_directories(inputs_);
  }

  ~Corpus() override {  // a read-only blocker would keep the folder from being removed
    for (const auto& e : fs::recursive_directory_iterator(out_))
      fs::permissions(e.path(), fs::perms::owner_all, fs::perm_options::add);
  }

  // The command line of `entry` for `backend` ("curvature" for a mesh's curvature run,
  // "strokefile" for a drawing's).
  std::string command(const json& entry, const std::string& backend) const {
    const std::string outputs = " -o " + out("image.exr") + " --dump-stages " + out("dump");
    if (entry.contains("mesh") && backend == "curvature")
      return "curvature " + input(entry["mesh"]) + " -o " + out("curvature.csv");
    if (entry.contains("svg"))
      return "strokefile builtin:torus --size 64x48 " + input(entry["svg"]) + " -o " + out("drawn.strokes.json");
    std::string render = "render --backend " + backend + " ";
    if (entry.contains("mesh")) return render + scene_for(entry["mesh"]) + outputs;
    if (entry.contains("scene")) return render + input(entry["scene"]) + outputs;
    if (entry.contains("strokes") || entry.contains("style")) return render + stroke_scene_for(entry) + outputs;
    return render + "builtin:torus " + replaced(entry["args"], "{out}", out_.string());
  }

  // An input's path: in the corpus, or absolute (/dev/zero), or made in the outputs' folder ({out}).
  std::string input(const json& name) const {
    return (kCorpus / replaced(name.get<std::string>(), "{out}", out_.string())).string();
  }

  // A 64x48 scene of the mesh with every pencil effect (curvature included); small
  // textures, which halve a run's time (the corpus tries the geometry, not them).
  std::string scene_for(const std::string& mesh) const {
    const std::string path = (inputs_ / (fs::path(mesh).stem().string() + ".json")).string();
    std::ofstream(path) << json{{"mesh", (kCorpus / mesh).string()},
                                {"resolution", {64, 48}},
                                {"effects", {"contours", "interior", "paper"}},
                                {"params", {{"pencil_textures.size", 64}, {"paper.size", 64}}}}
                               .dump();
    return path;
  }

  // A 64x48 scene of the torus as strokes that lists the entry's stroke file, or takes
  // its style for every kind of line.
  std::string stroke_scene_for(const json& entry) const {
    json scene = {{"objects", {{{"mesh", {{"procedural", "torus"}}}, {"style", "strokes"}}}}, {"resolution", {64, 48}}};
    if (entry.contains("strokes")) scene["stroke_files"] = {input(entry["strokes"])};
    if (entry.contains("style"))
      scene["strokes"] = {{"crease", input(entry["style"])}, {"silhouette", input(entry["style"])}};
    const std::string path = (inputs_ / "stroke_scene.json").string();
    std::ofstream(path) << scene.dump();
    return path;
  }

  // What the entry puts in the way or reads (a folder, a file, a read-only folder, a FIFO,
  // a file one byte over the input files' bound), made in the outputs' folder; its names.
  std::set<std::string> make_blockers(const json& entry) const {
    std::set<std::string> names;
    const json blockers = entry.value("blockers", json::object());
    for (const auto& [kind, name] : blockers.items()) {
      const fs::path p = out_ / name.get<std::string>();
      if (kind == "file") std::ofstream(p) << "in the way\n";
      if (kind == "folder" || kind == "read_only_folder") fs::create_directories(p);
      if (kind == "read_only_folder") fs::permissions(p, fs::perms::owner_write, fs::perm_options::remove);
      if (kind == "fifo" && ::mkfifo(p.c_str(), 0600) != 0) ADD_FAILURE() << "cannot make the FIFO " << p;
      if (kind == "oversize_file") {
        std::ofstream(p).put('{');
        fs::resize_file(p, kMaxInputFileBytes + 1);  // sparse: no disk used
      }
      names.insert(name.get<std::string>());
    }
    return names;
  }

  // The outcome `entry` expects of this run ("curvature" may differ from the renders').
  static std::string expected(const json& entry, const std::string& backend) {
    const bool own = backend == "curvature" && entry.contains("curvature");
    return (own ? entry["curvature"] : entry["expect"]).get<std::string>();
  }

  void check(const json& entry, const std::string& backend) {
    const std::set<std::string> blockers = make_blockers(entry);
    const std::string args = command(entry, backend);
    SCOPED_TRACE(backend + ": plumbago " + args);
    testing::CliRun r = testing::run_cli(args, logs_, limited());
    if (expected(entry, backend) == "refused")
      expect_refused(entry, backend, r);
    else
      expect_rendered(r);
    expect_nothing_but(blockers);
    fs::remove_all(out_);
    fs::create_directories(out_);
  }

  void expect_refused(const json& entry, const std::string& backend, const testing::CliRun& r) const {
    EXPECT_EQ(r.code, 2) << r.err;
    std::vector<std::string> needles = entry.value("message", std::vector<std::string>{});
    // A file's refusal names it; a mesh the scene refuses (its coordinates) is named by
    // the scene's key ("scene_key").
    for (const char* key : kInputKeys)
      if (entry.contains(key) && !(backend != "curvature" && entry.contains("scene_key")))
        needles.push_back(fs::path(entry[key].get<std::string>()).filename().string());
    if (entry.contains("scene_key") && backend != "curvature") needles.push_back(entry["scene_key"]);
    for (const auto& n : needles) EXPECT_NE(r.err.find(n), std::string::npos) << "'" << n << "' not in: " << r.err;
    // No library's exception text reaches the user (docs/bad-input.md, "The promise").
    for (const char* library : {"stod", "stoi", "_M_range_check", "bad_alloc", "-nan", "regex"})
      EXPECT_EQ(r.err.find(library), std::string::npos) << "'" << library << "' in: " << r.err;
  }

  // Exit code 0 and every image and text written finite; then the outputs are removed.
  void expect_rendered(const testing::CliRun& r) const {
    ASSERT_EQ(r.code, 0) << r.err;
    size_t images = 0;
    for (const auto& e : fs::recursive_directory_iterator(out_)) {
      if (e.path().extension() == ".exr") {
        ++images;
        EXPECT_FALSE(has_non_finite(read_image(e.path().string()))) << e.path();
      }
      if (e.path().extension() == ".csv" || e.path().extension() == ".json") {
        ++images;
        EXPECT_FALSE(has_word_nan_or_inf(testing::slurp(e.path().string()))) << e.path();
      }
    }
    EXPECT_GT(images, 0u) << "nothing written";
    for (const auto& e : fs::directory_iterator(out_)) fs::remove_all(e.path());
  }

  void expect_nothing_but(const std::set<std::string>& blockers) const {
    for (const auto& e : fs::recursive_directory_iterator(out_)) {
      const std::string name = fs::relative(e.path(), out_).string();
      EXPECT_TRUE(blockers.count(name)) << "left behind: " << name;
    }
  }

  std::string out(const std::string& name) const { return (out_ / name).string(); }

  json manifest_;
  testing::TempDir logs_;
  fs::path out_ = fs::path(logs_.dir()) / "out", inputs_ = fs::path(logs_.dir()) / "inputs";
};

TEST_P(Corpus, EveryEntryIsRefusedOrRenderedCleanlyOnBothBackends) {
  const bool root = ::geteuid() == 0;
  size_t entries = 0;
  for (const json& entry : manifest_["entries"]) {
    if (input_kind(entry) != GetParam()) continue;
    ++entries;
    SCOPED_TRACE(entry.dump());
    if (entry.contains("blockers") && entry["blockers"].contains("read_only_folder") && root) {
      std::printf("skipped (root writes into read-only folders): %s\n", entry.dump().c_str());
      continue;
    }
    try {
      if (entry.contains("mesh")) check(entry, "curvature");
      if (entry.contains("svg")) check(entry, "strokefile");
      for (const char* backend : {"gpu", "reference"})
        if (!entry.contains("svg")) check(entry, backend);
    } catch (const std::exception& e) {
      ADD_FAILURE() << "the entry cannot be run: " << e.what();
    }
  }
  EXPECT_GT(entries, 0u) << "no entry of this kind";
}

INSTANTIATE_TEST_SUITE_P(Inputs, Corpus, ::testing::Values("mesh", "scene", "svg", "strokes", "style", "args"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// Every file of the corpus has its entry, and every entry of the corpus its file (the
// others name /dev/zero or what the test makes in the outputs' folder).
TEST(CorpusManifest, ListsEveryFile) {
  std::set<std::string> listed, present;
  const json manifest = corpus_manifest();
  for (const json& entry : manifest["entries"])
    for (const char* key : kInputKeys)
      if (entry.contains(key) && entry[key].get<std::string>().starts_with(std::string(key) + "/"))
        listed.insert(entry[key].get<std::string>());
  for (const char* folder : kInputKeys)
    for (const auto& e : fs::directory_iterator(kCorpus / folder))
      present.insert(fs::relative(e.path(), kCorpus).string());
  EXPECT_EQ(listed, present);
  EXPECT_GE(listed.size(), 158u) << "the corpus has fewer files than issues 21 and 32 ask for";
}

}  // namespace
}  // namespace plumbago
