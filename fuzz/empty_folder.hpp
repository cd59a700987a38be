// A folder with nothing in it, made once per fuzz process: where the targets resolve the
// relative paths an input names (meshes, style files), so that they find nothing.
#pragma once

#include <filesystem>
#include <string>

namespace plumbago::fuzz {

inline const std::string& empty_folder() {
  static const std::string path = [] {
    std::filesystem::path p = std::filesystem::temp_directory_path() / "plumbago-fuzz-empty";
    std::filesystem::create_directories(p);
    return p.string();
  }();
  return path;
}

}  // namespace plumbago::fuzz
