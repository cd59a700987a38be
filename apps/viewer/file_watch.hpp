// The files a scene was read from (the scene file and its mesh files, or a mesh file
// opened alone), polled for changes: the viewer reloads the scene when one is edited.
#pragma once

#include <array>
#include <map>
#include <string>

#include "common/core/frame.hpp"

namespace plumbago {

// The scene of `source`: a scene file or builtin:NAME as `render` reads it, or a mesh
// file (any other file) as a scene of that one object, in `like`'s size, effects and
// parameters.
struct Scene;
Scene open_source(const std::string& source, const Scene& like);

class FileWatch {
 public:
  void watch(const std::string& source);  // nothing for a built-in scene
  // True once after a watched file changed (polled every half second at most).
  bool changed();

  using Stamp = std::array<long long, 4>;  // mtime s, ns, size, inode; zeros: no such file

 private:
  std::map<std::string, Stamp> files_;
  Stopwatch polled_;
};

}  // namespace plumbago
