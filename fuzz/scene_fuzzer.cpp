// libFuzzer target: parse_scene on the input as scene JSON. Relative mesh paths resolve
// against an empty folder (mesh loading has its own targets). A SceneError is a clean
// refusal; any other exception, a crash, a sanitizer report, a hang or runaway memory is
// a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/scene/scene.hpp"
#include "fuzz/empty_folder.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    plumbago::parse_scene(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json",
                          plumbago::fuzz::empty_folder());
  } catch (const plumbago::SceneError&) {
  }
  return 0;
}
