// libFuzzer target: load_mesh on the input, written to a file with the extension this
// target is built for (PLUMBAGO_FUZZ_EXTENSION), since the loader and OpenMesh read
// from a path. A MeshError is a clean refusal; any other exception, a crash, a sanitizer
// report, a hang or runaway memory is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/mesh/mesh.hpp"

namespace {

// One file per process, in $TMPDIR, removed at exit.
const std::string& input_path() {
  static const std::string path = [] {
    std::string p = (std::filesystem::temp_directory_path() /
                     ("plumbago-fuzz-" + std::to_string(getpid()) + PLUMBAGO_FUZZ_EXTENSION))
                        .string();
    std::atexit([] { std::remove(input_path().c_str()); });
    return p;
  }();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  {
    std::ofstream out(input_path(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  try {
    plumbago::load_mesh(input_path());
  } catch (const plumbago::MeshError&) {
  }
  return 0;
}
