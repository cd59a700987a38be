// GPU time of each pass of a frame.
//  - EGL build: GL timestamp queries (glQueryCounter) at the start and end of the pass.
//    (GL_TIME_ELAPSED is not used: llvmpipe on Mesa 22.3 answers the first elapsed-time
//    query around a freshly bound framebuffer with the time since boot.)
//  - OSMesa build: libOSMesa exports no timer-query entry points, so each pass ends
//    with glFinish and is timed by the wall clock (exact for llvmpipe, which runs on the
//    CPU, but it serializes the passes).
#pragma once

#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "gpu/gl/gl_objects.hpp"

namespace plumbago::gpu {

class PassTimer {
 public:
  void begin(const std::string& pass);
  void end();
  // Waits for every query of the frame and returns the GPU time of each pass.
  std::vector<PassTime> results();

 private:
  using Query = GlName<detail::delete_query>;
  struct Span {
    std::string pass;
    Query start, stop;
    Stopwatch wall;
    double wall_ms = 0;
  };
  std::vector<Span> spans_;
};

}  // namespace plumbago::gpu
