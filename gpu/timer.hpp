// GL timer queries (GL_TIME_ELAPSED) around each pass of a frame.
#pragma once

#include <string>
#include <vector>

#include "common/frame.hpp"
#include "gpu/gl_objects.hpp"

namespace plumbago::gpu {

class PassTimer {
 public:
  void begin(const std::string& pass);
  void end();
  // Waits for every query of the frame and returns the GPU time of each pass.
  std::vector<PassTime> results();

 private:
  struct Query {
    std::string pass;
    GlName<detail::delete_query> name;
  };
  std::vector<Query> queries_;
};

}  // namespace plumbago::gpu
