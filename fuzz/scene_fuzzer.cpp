// libFuzzer target: parse_scene on the input as scene JSON. Relative mesh paths resolve
// against an empty folder (mesh loading has its own targets). A SceneError is a clean
// refusal; any other exception, a crash, a sanitizer report, a hang or runaway memory is
// a finding.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "common/scene/scene.hpp"

namespace {

const std::string& empty_folder() {
  static const std::string path = [] {
    std::filesystem::path p = std::filesystem::temp_directory_path() / "plumbago-fuzz-empty";
    std::filesystem::create_directories(p);
    return p.string();
  }();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    plumbago::parse_scene(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json", empty_folder());
  } catch (const plumbago::SceneError&) {
  }
  return 0;
}
