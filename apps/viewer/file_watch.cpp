#include "apps/viewer/file_watch.hpp"

#include <sys/stat.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "common/scene/scene.hpp"

namespace plumbago {
namespace {

namespace fs = std::filesystem;

constexpr double kPollMs = 500;

bool is_scene_file(const std::string& source) { return fs::path(source).extension() == ".json"; }

// What tells an edit: the time of the last write (coarse: two writes within a few ms
// may share it), the size and the inode (an editor's save by rename makes a new one).
FileWatch::Stamp stamp(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return {};
  return {(long long)st.st_mtim.tv_sec, (long long)st.st_mtim.tv_nsec, (long long)st.st_size, (long long)st.st_ino};
}

// The scene file and the mesh files it names, or the mesh file itself.
std::vector<std::string> files_of(const std::string& source) {
  std::vector<std::string> files{source};
  if (!is_scene_file(source)) return files;
  nlohmann::json j = nlohmann::json::parse(scene_text(source), nullptr, false);
  if (!j.is_object() || !j["objects"].is_array()) return files;
  for (const auto& o : j["objects"])
    if (o.is_object() && o.contains("mesh") && o["mesh"].is_string())
      files.push_back((fs::path(scene_folder(source)) / o["mesh"].get<std::string>()).string());
  return files;
}

}  // namespace

Scene open_source(const std::string& source, const Scene& like) {
  if (is_scene_file(source) || source.rfind("builtin:", 0) == 0) return load_scene(source);
  nlohmann::json doc{{"objects", {{{"mesh", fs::absolute(source).string()}}}},
                     {"resolution", {like.width, like.height}},
                     {"effects", like.effects}};
  Scene s = parse_scene(doc.dump(), source, fs::path(source).parent_path().string());
  s.params = like.params;
  match_effects_to_styles(s);
  return s;
}

void FileWatch::watch(const std::string& source) {
  files_.clear();
  if (source.rfind("builtin:", 0) == 0) return;
  for (const std::string& f : files_of(source)) files_[f] = stamp(f);
}

bool FileWatch::changed() {
  if (polled_.ms() < kPollMs) return false;
  polled_ = Stopwatch();
  bool any = false;
  for (auto& [path, last] : files_) {
    Stamp now = stamp(path);
    any |= now != last;
    last = now;
  }
  return any;
}

}  // namespace plumbago
